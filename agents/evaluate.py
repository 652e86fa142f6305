"""``python -m agents.evaluate`` = ``laddermill evaluate`` (:mod:`laddermill_gym.harness.evaluate`)."""

import sys

from laddermill_gym.harness.evaluate import main

if __name__ == "__main__":
    sys.exit(main())
