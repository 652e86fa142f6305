"""A command's parser written once for its two ways of running: as a subcommand of ``laddermill`` (on an argparse
subparsers object) and as a program of its own (``main(argv)``: ``laddermill NAME`` forwards to it, and
``python -m`` runs it). Plain argparse: imports nothing of the package."""

from __future__ import annotations

import argparse
import sys
from collections.abc import Callable
from dataclasses import dataclass


@dataclass(frozen=True)
class Command:
    """The command ``laddermill NAME``: its ``help`` line in ``laddermill -h``, its ``description`` (the text of
    its own help), ``arguments`` (adds its options and arguments to a parser) and ``run`` (runs it on the parsed
    arguments; the exit status). A module binds ``add_parser = COMMAND.add_parser`` and ``main = COMMAND.main``."""

    name: str
    help: str
    description: str
    arguments: Callable[[argparse.ArgumentParser], None]
    run: Callable[[argparse.Namespace], int]

    def add_parser(self, sub) -> argparse.ArgumentParser:
        """The command on the argparse subparsers ``sub`` (sets ``func`` to :attr:`run`)."""
        p = sub.add_parser(self.name, help=self.help, description=self.description)
        self.arguments(p)
        p.set_defaults(func=self.run)
        return p

    def main(self, argv: list[str] | None = None) -> int:
        """Parse ``argv`` (None: the process' arguments) with a parser of its own, ``laddermill NAME``, and run."""
        p = argparse.ArgumentParser(prog=f"laddermill {self.name}", description=self.description)
        self.arguments(p)
        return self.run(p.parse_args(argv))


def run_subcommand(add_parser: Callable, name: str, argv: list[str] | None = None, prog: str = "laddermill",
                   dest: str = "cmd"):
    """Parse ``argv`` (None: the process' arguments) as ``prog name ARGV`` with the parser ``add_parser(sub)``
    puts on a subparsers object, and return what its ``func`` returns."""
    parser = argparse.ArgumentParser(prog=prog)
    add_parser(parser.add_subparsers(dest=dest, required=True))
    args = parser.parse_args([name, *(sys.argv[1:] if argv is None else argv)])
    return args.func(args)
