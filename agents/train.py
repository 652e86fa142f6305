"""``python -m agents.train`` = ``laddermill train`` (:mod:`laddermill_gym.harness.train`)."""

import sys

from laddermill_gym.harness.train import main

if __name__ == "__main__":
    sys.exit(main())
