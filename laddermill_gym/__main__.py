import sys

from laddermill_gym.cli import main

sys.exit(main())
