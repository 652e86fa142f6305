"""Which number of which docs page is checked against a command, and what every other number on a page is.

Every page of ``laddermill_gym/docs/`` is in :data:`LEDGER`: either a :class:`Covered` page, whose every quoted
number (:mod:`docsite.page_numbers`) is accounted for by one of its entries, or a :class:`NotYet` page with the reason
its numbers are not all checked yet (with the checks it has already). ``tests/test_page_figures.py`` enforces both
in the fast set (a page not in the ledger, a number on a covered page that no entry accounts for, or an entry that
matches nothing fails it); the slow set re-runs the checks (``python -m docsite.readme_figures --pages``).

A covered page's entries:

* ``checks``: (a regular expression over the page's flattened text, its groups' expected texts as ``str.format``
  templates over the measured figures, ``{group[key]...}``): the groups are re-run and compared exactly, to the
  printed digits (a ``~`` template: the printed value rounded to the quoted digits); a check whose template names a
  long group (a gust scorecard) is compared by ``--long`` (:mod:`docsite.long_checks`);
* ``given``: snippets whose numbers are inputs (a command's settings, a scene's size), the papers' own figures,
  equation and figure numbers, dates and versions: nothing to re-run;
* ``timings``: snippets whose numbers are machine timings (durations, real-time factors, memory of a process):
  dated measurements, each with its machine and load on the page, not compared;
* ``derived``: snippets whose numbers are worked by hand from checked ones or read off a picture (no command
  prints them): listed so that a reader of this file sees them;
* ``printed``: :class:`~docsite.ledger_kinds.Printed` entries, snippets each of whose numbers a group's command
  prints (the printed value rounded to the quoted digits, near one another in its whole output:
  :mod:`docsite.printed_numbers`); the group is a page
  group (re-run with the page) or a long group (:mod:`docsite.long_figures`: minutes to hours, re-run only by
  ``python -m docsite.readme_figures --long NAME``; ``--long --list`` names them with their commands);
* ``history``: :class:`~docsite.ledger_kinds.History` records, figures of dated runs that are not kept (training runs,
  runs of earlier code, trials on modified configs): each names its date, command and run, and the page marks the
  snippet's paragraph, caption or section with that date (:mod:`docsite.page_history`, tests/test_page_history.py);
* ``not_rerun``: snippets whose numbers no command prints (a test's assertion, a Python session's, a count inside a
  fit): the gap, stated.
"""

from __future__ import annotations

from docsite.ledger_benchmarks import BENCHMARKS
from docsite.ledger_closed_loop import WORK_PRECISION_CLOSED_LOOP
from docsite.ledger_cold_start import COLD_START
from docsite.ledger_cold_start_machines import COLD_START_MACHINES
from docsite.ledger_cold_start_mill import COLD_START_MILL
from docsite.ledger_controllers import CONTROLLERS
from docsite.ledger_craft import ROTOR, ROTORCRAFT
from docsite.ledger_data import CABLE_DATA
from docsite.ledger_design import ROTOR_DESIGN
from docsite.ledger_guides import ABOUT_DOCS, GETTING_STARTED, INDEX, MODEL, RL_ZOO3, SCALE_OUT
from docsite.ledger_kinds import Covered, NotYet
from docsite.ledger_learned import LEARNED_MILL
from docsite.ledger_meijaard import MEIJAARD
from docsite.ledger_mill import FEATURES, MOVING_CABLE
from docsite.ledger_mill_fast import MILL_FAST
from docsite.ledger_numerics import NUMERICS
from docsite.ledger_papers import LANSDORP, PODGAETS, ROBERTS
from docsite.ledger_pointmass import POINTMASS, POINTMASS_MILL
from docsite.ledger_power_curve import POWER_CURVE
from docsite.ledger_precision import WORK_PRECISION
from docsite.ledger_pumping import PUMPING
from docsite.ledger_quasisteady import QUASISTEADY
from docsite.ledger_reeling import REELING
from docsite.ledger_scorecard_step import SCORECARD_STEP
from docsite.ledger_studies import LATERAL
from docsite.ledger_wind import WIND
from docsite.ledger_wing import WING_DATA

__all__ = ["LEDGER", "Covered", "NotYet"]

#: Every docs page: covered, or why not yet.
LEDGER = {
    "about_docs.md": ABOUT_DOCS,
    # the page is ARCHITECTURE.md included whole; the coverage reads the page's own text, which is only the include
    "architecture.md": NotYet("it includes ARCHITECTURE.md, whose figures (compile and CPU times, counts) the "
                              "coverage does not read: no ledger accounts for them"),
    "command_line.md": Covered(given=("does about 40 s after the direction step",
                                      # the CLI's exit statuses (cli.run_guarded, cmd_simulate's --allow-breakdown)
                                      "with exit status 3 ( : 0,",
                                      "keeps what it has, with exit status 0 (1 with );")),
    "getting_started.md": GETTING_STARTED,
    "index.md": INDEX,
    "layout.md": Covered(given=("eq. (6)",)),
    "paper_roberts.md": ROBERTS,
    "usage.md": Covered(given=("a pole at 0 for",)),
    "benchmarks.md": BENCHMARKS,
    "cable_data.md": CABLE_DATA,
    "cold_start.md": COLD_START,
    "cold_start_mill.md": COLD_START_MILL,
    "cold_start_machines.md": COLD_START_MACHINES,
    "controllers.md": CONTROLLERS,
    "scorecard_physics_step.md": SCORECARD_STEP,
    "features.md": FEATURES,
    "lateral_stability.md": LATERAL,
    "learned_mill.md": LEARNED_MILL,
    "mill_fast.md": MILL_FAST,
    "model.md": MODEL,
    "moving_cable.md": MOVING_CABLE,
    "numerics.md": NUMERICS,
    "paper_lansdorp2008.md": LANSDORP,
    "paper_meijaard1999.md": MEIJAARD,
    "paper_podgaets2007.md": PODGAETS,
    "pointmass.md": POINTMASS,
    "pointmass_mill.md": POINTMASS_MILL,
    "power_curve.md": POWER_CURVE,
    "pumping.md": PUMPING,
    "quasisteady.md": QUASISTEADY,
    "reeling_tether.md": REELING,
    "rl_zoo3.md": RL_ZOO3,
    "rotor.md": ROTOR,
    "rotorcraft.md": ROTORCRAFT,
    "rotorcraft_design.md": ROTOR_DESIGN,
    "scale_out.md": SCALE_OUT,
    "wind.md": WIND,
    "wing_data.md": WING_DATA,
    "work_precision.md": WORK_PRECISION,
    "work_precision_closed_loop.md": WORK_PRECISION_CLOSED_LOOP,
}
