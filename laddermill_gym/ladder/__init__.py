"""The wing-and-cable systems: scenes read from YAML, the chain's initial state. Imports ``sim`` and below."""
