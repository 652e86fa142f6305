"""``python -m agents.lqr`` = ``laddermill lqr`` (:mod:`laddermill_gym.harness.lqr_report`)."""

import sys

from laddermill_gym.harness.lqr_report import main

if __name__ == "__main__":
    sys.exit(main())
