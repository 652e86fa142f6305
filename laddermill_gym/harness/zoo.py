"""Run an rl-zoo3 script with the laddermill_gym environments registered (needs the ``zoo`` extra).

    python -m laddermill_gym.harness.zoo [--save FIGURE] SCRIPT [rl-zoo3 arguments ...]
    python -m laddermill_gym.harness.zoo train --algo ppo --env laddermill_gym/TetheredWing-v0
    python -m laddermill_gym.harness.zoo record_video --algo ppo --env laddermill_gym/TetheredWing-v0 -f logs -n 400
    python -m laddermill_gym.harness.zoo --save curve.png plot_train -a ppo -e TetheredWing -f logs -w 10

SCRIPT is one of :data:`SCRIPTS` (rl-zoo3's ``python -m rl_zoo3.<module>``). ``rl_zoo3.train`` and
``rl_zoo3.enjoy`` take ``--gym-packages laddermill_gym`` and need no wrapper; ``rl_zoo3.record_video`` and
``rl_zoo3.record_training`` have no such option and find the ids only when ``laddermill_gym`` is imported first,
which this command does. It also fills in what rl-zoo3 would otherwise take from its own defaults:

* ``train``: ``--conf-file`` our shipped ``configs/rl_zoo3/<algo>.yaml`` (PPO, SAC) when none is given;
* ``train``, ``enjoy``: ``--num-threads`` as ``laddermill train`` chooses it (``$LADDERMILL_TORCH_THREADS``, else
  1) when none is given: rl-zoo3's default is torch's, one thread per core, several times slower here;
* the plot scripts: ``--save FIGURE`` (before SCRIPT; everything after SCRIPT is rl-zoo3's) writes every
  figure the script draws to FIGURE (``curve.png``, ``curve_2.png``, ...) instead of opening a window (they only
  call ``matplotlib.pyplot.show``).
"""

from __future__ import annotations

import argparse
import runpy
import sys
import warnings
from pathlib import Path

from laddermill_gym.model.configio import CONFIG_DIR
from laddermill_gym.studies.commands import Parser, UsageError

#: the rl-zoo3 scripts this command runs: name -> module
SCRIPTS: dict[str, str] = {
    "train": "rl_zoo3.train", "enjoy": "rl_zoo3.enjoy", "record_video": "rl_zoo3.record_video",
    "record_training": "rl_zoo3.record_training", "plot_train": "rl_zoo3.plots.plot_train",
    "all_plots": "rl_zoo3.plots.all_plots", "plot_from_file": "rl_zoo3.plots.plot_from_file",
}
#: our rl-zoo3 hyperparameter files, one per algorithm
ZOO_CONFIGS: dict[str, Path] = {"ppo": CONFIG_DIR / "rl_zoo3" / "ppo.yaml", "sac": CONFIG_DIR / "rl_zoo3" / "sac.yaml"}


def _given(args: list[str], *names: str) -> bool:
    return any(a == n or a.startswith(n + "=") for a in args for n in names)


def _value(args: list[str], *names: str) -> str | None:
    for i, a in enumerate(args):
        for n in names:
            if a == n and i + 1 < len(args):
                return args[i + 1]
            if a.startswith(n + "="):
                return a[len(n) + 1:]
    return None


def script_arguments(script: str, args: list[str]) -> list[str]:
    """``args`` with the defaults this command adds (module docstring) for ``script``."""
    from laddermill_gym.harness.train import torch_threads

    out = list(args)
    if script == "train" and not _given(out, "--conf-file", "-conf", "--conf"):
        algo = _value(out, "--algo") or "ppo"  # rl-zoo3's default algorithm
        if algo in ZOO_CONFIGS:
            out += ["--conf-file", str(ZOO_CONFIGS[algo])]
    if script in ("train", "enjoy") and not _given(out, "--num-threads"):
        out += ["--num-threads", str(torch_threads())]
    return out


def _saving_show(figure: Path):
    """A replacement of ``pyplot.show`` that saves every open figure (``figure``, ``figure_2``, ...)."""
    import matplotlib.pyplot as plt

    def show(*_args, **_kwargs) -> None:
        for k, num in enumerate(plt.get_fignums()):
            name = figure if k == 0 else figure.with_name(f"{figure.stem}_{k + 1}{figure.suffix}")
            plt.figure(num).savefig(name, dpi=120)
            print(f"wrote {name}")
        plt.close("all")

    return show


def run_script(script: str, args: list[str], save: Path | None = None) -> None:
    """Run rl-zoo3's ``script`` as ``python -m`` would, with ``laddermill_gym`` imported (its ids registered).
    rl-zoo3's scripts read ``sys.argv``, so it is set for the run and restored afterwards."""
    import laddermill_gym  # noqa: F401  (registers the environments)

    restore = _save_shown_figures(save) if save is not None else None
    argv = sys.argv
    sys.argv = [SCRIPTS[script], *script_arguments(script, args)]
    try:
        with warnings.catch_warnings():  # rl_zoo3.plots imports its scripts in __init__; runpy warns about it
            warnings.filterwarnings("ignore", message=".*found in sys.modules after import of package",
                                    category=RuntimeWarning)
            runpy.run_module(SCRIPTS[script], run_name="__main__", alter_sys=True)
    finally:
        sys.argv = argv
        if restore is not None:
            restore()


def _save_shown_figures(save: Path):
    """Point pyplot at Agg with ``show`` saving to ``save`` (rl-zoo3's plot scripts draw with pyplot and call
    ``show``); returns the function that puts the caller's backend and ``show`` back."""
    import matplotlib
    import matplotlib.pyplot as plt

    backend, show = matplotlib.get_backend(), plt.show
    plt.switch_backend("Agg")
    plt.show = _saving_show(save)

    def restore() -> None:
        plt.show = show
        plt.switch_backend(backend)

    return restore


def add_parser(sub) -> argparse.ArgumentParser:
    """``laddermill zoo`` on the subparsers ``sub`` (sets ``func``)."""
    p = sub.add_parser("zoo", help="run an rl-zoo3 script (train, enjoy, record_video, plot_train, ...) with the "
                       "laddermill_gym environments registered", description=__doc__.split("\n\n")[0].replace("``", ""))
    _arguments(p)
    p.set_defaults(func=lambda a: _run(a, p))
    return p


def _arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument("script", choices=sorted(SCRIPTS), help="the rl-zoo3 script")
    p.add_argument("--save", type=Path, help="plot scripts: save the figures to this file instead of showing them "
                   "(give it before SCRIPT)")
    p.add_argument("args", nargs=argparse.REMAINDER, help="the script's own arguments (python -m rl_zoo3.<script> "
                   "-h lists them)")


def _run(a: argparse.Namespace, p: argparse.ArgumentParser) -> int:
    try:
        import rl_zoo3  # noqa: F401
    except ImportError:
        p.error("rl_zoo3 is not installed: pip install 'laddermill_gym[zoo]' (or pip install rl_zoo3)")
    if a.save is not None and not a.script.startswith(("plot", "all_plots")):
        p.error(f"--save applies to the plot scripts, not {a.script}")
    folder = _value(a.args, "--folder", "-f")
    if a.script in ("enjoy", "record_video", "record_training") and folder is not None and not Path(folder).is_dir():
        raise UsageError(f"{a.script} --folder = {folder!r}: no such folder (rl-zoo3's log folder, logs/ by default "
                         "of its train)")
    try:
        run_script(a.script, a.args, a.save)
    except SystemExit as stop:  # the scripts' own argparse errors and exits
        return stop.code if isinstance(stop.code, int) else (0 if stop.code is None else 1)
    except AssertionError as err:  # rl-zoo3 checks its input with assert ("The logs/ppo folder was not found")
        raise UsageError(f"rl_zoo3 {a.script}: {err}") from None
    return 0


def main(argv: list[str] | None = None) -> int:
    p = Parser(prog="laddermill zoo", description=__doc__.split("\n\n")[0].replace("``", ""))
    _arguments(p)
    return _run(p.parse_args(argv), p)


if __name__ == "__main__":
    from laddermill_gym.studies.commands import run_guarded

    raise SystemExit(run_guarded("zoo", main))
