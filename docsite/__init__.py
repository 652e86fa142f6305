"""The documentation site's build code (MkDocs hooks, env pages, tutorial runner); not installed with the package."""
