"""A command's parser written once for its two ways of running: as a subcommand of ``laddermill`` (on an argparse
subparsers object) and as a program of its own (``main(argv)``: ``laddermill NAME`` forwards to it, and
``python -m`` runs it); the one-line argparse errors (:class:`Parser`), option checks (:func:`check_number`,
:func:`check_controllers`, :func:`writable_folder`, :class:`UsageError`) and the guard that turns bad input into one
line and exit status 2 (:func:`run_guarded`) every command uses. Plain argparse; of the package only the configs'
lookup (``model.configio``) and the simulator's refusal (``sim.simulator.SimulationError``), imported where used."""

from __future__ import annotations

import argparse
import math
import sys
from collections.abc import Callable
from dataclasses import dataclass


class UsageError(ValueError):
    """Bad command-line input: ``laddermill`` prints it as one line, ``laddermill NAME: error: ...``, exit status 2."""


class Parser(argparse.ArgumentParser):
    """argparse with its errors on one line, ``PROG: error: MESSAGE (see PROG --help)``, exit status 2 (argparse's
    own error prints the whole usage first); subcommand parsers made from it are of the same kind."""

    def error(self, message: str):
        self.exit(2, f"{self.prog}: error: {message} (see {self.prog} --help)\n")


def _plain(x: float) -> str:
    """A bound as written: whole numbers in full (4294967295), others as %g."""
    return str(int(x)) if float(x).is_integer() and abs(x) < 1e16 else f"{x:g}"


def check_number(name: str, value, *, low: float | None = None, high: float | None = None, integer: bool = False,
                 strict: bool = True, unit: str = "") -> None:
    """UsageError naming the option ``name`` and ``value`` unless it is a finite number (a whole one with
    ``integer``) above ``low`` (at least ``low`` when not ``strict``) and at most ``high``; None passes."""
    if value is None:
        return
    ok = isinstance(value, (int, float)) and math.isfinite(value) and (not integer or int(value) == value)
    ok = ok and (low is None or (value > low if strict else value >= low)) and (high is None or value <= high)
    if not ok:
        kind = "a whole number" if integer else "a finite number"
        span = [f"{'>' if strict else '>='} {_plain(low)}" if low is not None else "",
                f"<= {_plain(high)}" if high is not None else ""]
        raise UsageError(f"{name} = {value!r}: must be {kind} {' and '.join(x for x in span if x)}".rstrip()
                         + (f" {unit}" if unit else ""))


def writable_folder(path, option: str = "--out"):
    """The output folder ``path``, created now (so that a bad path fails before any simulation); UsageError naming
    ``option`` if it is a file or cannot be written."""
    from pathlib import Path

    out = Path(path)
    if out.exists() and not out.is_dir():
        raise UsageError(f"{option} = {str(path)!r}: is a file, not a folder")
    try:
        out.mkdir(parents=True, exist_ok=True)
        probe = out / ".laddermill_write_test"
        probe.write_bytes(b"")
        probe.unlink()
    except OSError as err:
        raise UsageError(f"{option} = {str(path)!r}: cannot write there ({err.strerror or err})") from None
    return out


def writable_file(path, option: str = "--out", suffixes: tuple = ()):
    """The output file ``path``, checked now (so that a bad path fails before the work): its folder created and
    written to (:func:`writable_folder`); UsageError naming ``option`` if it is a folder, or if ``suffixes`` are given
    and it ends in none of them."""
    from pathlib import Path

    out = Path(path)
    if suffixes and out.suffix.lower() not in suffixes:
        raise UsageError(f"{option} = {str(path)!r}: the file must end in one of {', '.join(suffixes)}")
    if out.is_dir():
        raise UsageError(f"{option} = {str(path)!r}: is a folder; give a file name")
    folder = out.parent
    if folder.exists() and not folder.is_dir():
        raise UsageError(f"{option} = {str(path)!r}: its folder {str(folder)!r} is a file")
    try:
        writable_folder(folder, option)
    except UsageError:  # name the file given and its folder
        raise UsageError(f"{option} = {str(path)!r}: cannot write into its folder {str(folder)!r}") from None
    return out


def run_guarded(name: str, run) -> int:
    """The exit status of ``run()``, the command ``laddermill name``: bad input (UsageError, ConfigError) one line
    on stderr and 2; a start state or setting the simulator refuses (SimulationError) one line and 3; Ctrl-C one line
    and 130 (a command that keeps its partial results says so itself); a reader that closed the output pipe, nothing
    and 141 (as a tool ended by SIGPIPE)."""
    from laddermill_gym.model.configio import ConfigError
    from laddermill_gym.sim.simulator import SimulationError

    try:
        status = int(run() or 0)
        sys.stdout.flush()  # a pipe's block buffer is written here, not at the interpreter's exit, past this guard
        return status
    except (UsageError, ConfigError, SimulationError) as err:  # bad input: one line, no traceback
        text = " ".join(line.strip() for line in str(err).splitlines() if line.strip())
        print(f"laddermill {name}: error: {text}", file=sys.stderr)
        return 3 if isinstance(err, SimulationError) else 2
    except KeyboardInterrupt as err:  # a batch on workers says what each task did (studies/parallel.TasksInterrupted)
        print(f"laddermill {name}: interrupted (Ctrl-C)" + (f": {err}" if str(err) else ""), file=sys.stderr)
        return 130
    except BrokenPipeError:  # the reader of the output left (``laddermill scenes | head``): end quietly, as a shell
        if not _stdout_reader_left():  # tool ended by SIGPIPE; a pipe or socket of the command's own: its traceback
            raise
        import os  # later writes (the interpreter's flush at exit) go nowhere

        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return 141


def _stdout_reader_left() -> bool:
    """Whether standard output is a pipe whose reader has closed it (poll reports an error on its write end); True
    where the platform has no ``select.poll`` (it cannot tell)."""
    import select

    if not hasattr(select, "poll"):
        return True
    try:
        poller = select.poll()
        poller.register(sys.stdout.fileno(), select.POLLOUT)
        return any(events & (select.POLLERR | select.POLLHUP) for _, events in poller.poll(0))
    except (AttributeError, OSError, ValueError):  # no file descriptor (a captured stream)
        return False


def check_controllers(specs, option: str = "--controllers") -> None:
    """UsageError naming ``option`` and the first controller spec that is none of: ``open_loop``, ``lqr``,
    ``lqr:CONFIG`` (an LQR config file or a shipped name, ``lqr_tethered_wing``), the rotorcraft's ``lqr_guard`` and
    ``lqr_guard:CONFIG``, the pumping kite's ``scripted``,
    ``crosswind`` and ``crosswind:CONFIG``, a shipped policy's name (``ppo_tethered_wing``), an existing path (a
    training run folder, a model file, an rl-zoo3 log folder). Checked before any environment is built."""
    from pathlib import Path

    from laddermill_gym.control.shipped_policies import SHIPPED_POLICIES
    from laddermill_gym.model.configio import ConfigError, find_config

    for spec in specs:
        prefixed = ("lqr:", "lqr_guard:", "crosswind:")
        if spec in ("open_loop", "lqr", "lqr_guard", "scripted", "crosswind") or spec in SHIPPED_POLICIES or (
                not spec.startswith(prefixed) and Path(spec).exists()):
            continue
        if spec.startswith(prefixed):
            try:
                find_config("agents", spec.split(":", 1)[1])
            except ConfigError as err:
                raise UsageError(f"{option} {spec!r}: {err}") from None
            continue
        raise UsageError(f"{option} {spec!r}: not open_loop, lqr, lqr:<config>, lqr_guard, scripted, crosswind, "
                         f"crosswind:<config>, a shipped policy ({', '.join(sorted(SHIPPED_POLICIES))}) or an "
                         "existing run folder, model file or rl-zoo3 log folder")


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
        """Parse ``argv`` (None: the process' arguments) with a parser of its own, ``laddermill NAME``, and run
        (:func:`run_guarded`: bad input one line and exit status 2, as ``laddermill NAME``)."""
        p = Parser(prog=f"laddermill {self.name}", description=self.description)
        self.arguments(p)
        args = p.parse_args(argv)
        return run_guarded(self.name, lambda: self.run(args))


def run_subcommand(add_parser: Callable, name: str, argv: list[str] | None = None, prog: str = "laddermill",
                   dest: str = "cmd"):
    """Parse ``argv`` (None: the process' arguments) as ``prog name ARGV`` with the parser ``add_parser(sub)``
    puts on a subparsers object, and return what its ``func`` returns (:func:`run_guarded`)."""
    parser = Parser(prog=prog)
    add_parser(parser.add_subparsers(dest=dest, required=True))
    args = parser.parse_args([name, *(sys.argv[1:] if argv is None else argv)])
    return run_guarded(name, lambda: args.func(args))
