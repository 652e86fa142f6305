"""``python -m agents.train`` = ``laddermill train``: the same command line, bad input reported as one line (exit
status 2)."""

import sys

from laddermill_gym.cli import main

if __name__ == "__main__":
    sys.exit(main(["train", *sys.argv[1:]]))
