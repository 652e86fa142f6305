# Developer shortcuts (run inside the project's venv)
.PHONY: test slow lint bench simulate

test:
	python -m pytest -q

slow:
	python -m pytest -q -m slow

lint:
	python -m ruff check laddermill_gym tests agents

bench:
	laddermill bench --json bench.json

simulate:
	laddermill simulate tethered_wing --time 120 --direction-step 0.01 --out runs
