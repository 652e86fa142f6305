# Developer shortcuts (run inside the project's venv)
.PHONY: test slow lint bench simulate figures gust-bench work-precision docs readme-figures

test:
	python -m pytest -n 2 -q

slow:
	python -m pytest -q -m slow

lint:
	python -m ruff check laddermill_gym tests agents

bench:
	laddermill bench --json bench.json

# the documentation site into build/site/ (pip install -e ".[docs]"): warnings, broken links and anchors fail it, and it
# runs the tutorials (about 2-3 minutes; laddermill_gym/docs/about_docs.md)
docs:
	NO_MKDOCS_2_WARNING=1 mkdocs build --strict

# re-run the figures README and docs/controllers.md quote (main job, env sizes, TetheredWing-v0's open-loop and LQR
# rows; --policies: the shipped policies' gusts-v1 scorecards, ppo_mill's row; --papers: the Papers-reproduced rows,
# each study in turn: docsite/paper_figures.py) into results/readme_figures.json and fail naming any the text no
# longer matches (10 minutes on a quiet 2-core machine, about 35 at a load of 5-8); --pages: the docs pages' checked
# numbers (docsite/page_ledger.py; one page alone: --skip-readme --pages NAME); --pictures: every embedded picture
# drawn again by its command into docs/figures/ (docsite/pictures.py: each command with its cost; training runs left out)
readme-figures:
	python -m docsite.readme_figures --policies --papers --pages --pictures --out results/readme_figures.json

gust-bench:
	laddermill gust-bench --suite gusts-v1 --controllers open_loop lqr --out results/gust_bench/gusts-v1
	laddermill gust-bench --suite gusts-v1 --env laddermill_gym/TetheredWing-v0 \
		--controllers open_loop lqr runs/ppo_tethered_wing_seed0 --out results/gb_tw
	cp results/gb_tw/scorecard_TetheredWing-v0.png $(FIG)/gust_scorecard_tethered_wing.png
	laddermill gust-bench --suite gusts-v1 --env laddermill_gym/Rotorcraft-v0 \
		--controllers open_loop lqr runs/ppo_rotorcraft_seed0 --out results/gb_rc
	cp results/gb_rc/scorecard_Rotorcraft-v0.png $(FIG)/gust_scorecard_rotorcraft.png

# docs/work_precision.md: its figures and tables (about 15 minutes, one thread each)
WP = NUMBA_NUM_THREADS=1 laddermill work-precision
work-precision:
	$(WP) ladder_chain --time 10 --samples 50 --out results/work_precision
	$(WP) tethered_wing roberts_flying_model laddermill --time 5 --samples 25 --out results/work_precision
	$(WP) podgaets_5km --time 10 --samples 50 --out results/work_precision
	$(WP) pumping_kite roberts_35m_15kft roberts_35m_30kft --forcing step --time 5 --samples 25 --out results/work_precision
	for s in ladder_chain tethered_wing roberts_flying_model laddermill podgaets_5km pumping_kite roberts_35m_15kft roberts_35m_30kft; do \
		cp results/work_precision/$$s.png $(FIG)/work_precision_$$s.png; done
	$(WP) laddermill --forcing step --time 10 --samples 50 --out results/work_precision_10s
	cp results/work_precision_10s/laddermill.png $(FIG)/work_precision_laddermill_10s.png

simulate:
	laddermill demo --out runs
	cp runs/demo.png laddermill_gym/docs/figures/laddermill_demo.png
	laddermill simulate laddermill --start periodic --direction-step 0.01 --time 60 --animate --allow-breakdown --out runs
	cp runs/laddermill_shape.png laddermill_gym/docs/figures/laddermill_direction_step.png
	cp runs/laddermill_generator.png laddermill_gym/docs/figures/laddermill_generator.png
	laddermill simulate tethered_wing --time 120 --direction-step 0.01 --out runs
	cp runs/tethered_wing_histories.png laddermill_gym/docs/figures/tethered_wing_direction_step.png

# README figures and tables: chain controllers, PPO training (about 25 minutes), tethered-wing controllers
FIG = laddermill_gym/docs/figures
RUN = runs/ppo_tethered_wing_seed0
figures:
	laddermill evaluate --env laddermill_gym/LadderChain-v0 --episodes 1 --out results/ladder_chain \
		--controllers open_loop lqr lqr:configs/agents/lqr_ladder_chain_central.yaml
	cp results/ladder_chain/lateral.png $(FIG)/ladder_chain_controllers.png
	python -m laddermill_gym.studies.rotorcraft.craft_stability --out results/craft_stability
	cp results/craft_stability/rotorcraft_stability.png $(FIG)/rotorcraft_stability.png
	python -m laddermill_gym.studies.rotorcraft.rotor_chart --out $(FIG)/rotor_power_chart.png --csv results/rotor_power_chart.csv
	python -m laddermill_gym.studies.mill.meijaard --out results/meijaard_v1
	for f in fig6_shapes fig7_tension fig8_direction_step claims; do \
		cp results/meijaard_v1/$$f.png $(FIG)/meijaard_v1_$$f.png; done
	python -m laddermill_gym.studies.mill.meijaard --scene laddermill --out results/meijaard
	cp results/meijaard/fig6_shapes.png $(FIG)/meijaard_fig6_shapes.png
	cp results/meijaard/fig7_tension.png $(FIG)/meijaard_fig7_tension.png
	cp results/meijaard/fig8_direction_step.png $(FIG)/meijaard_fig8_direction_step.png
	python -m agents.train configs/agents/ppo_tethered_wing.yaml --out $(RUN)
	cp $(RUN)/training_curve.png $(FIG)/ppo_training_curve.png
	laddermill evaluate --controllers open_loop lqr $(RUN)/best_model.zip $(RUN)/model.zip --episodes 1 \
		--out results/tethered_wing
	cp results/tethered_wing/lateral.png $(FIG)/tethered_wing_controllers.png
	python -m laddermill_gym.studies.pumping.pumping_cycle --cycles 2 --out results/pumping_cycle
	cp results/pumping_cycle/pumping_window.png $(FIG)/pumping_crosswind_window.png
	cp results/pumping_cycle/pumping_timeseries.png $(FIG)/pumping_crosswind_timeseries.png
	python -m laddermill_gym.studies.pumping.power_curve --out results/pumping_power
	cp results/pumping_power/pumping_power_curve.png $(FIG)/pumping_power_curve.png
	python -m laddermill_gym.studies.pumping.power_curve --reel-element-length 40 --out results/pumping_power_reeling
	cp results/pumping_power_reeling/pumping_power_curve.png $(FIG)/pumping_power_curve_reeling.png
	for s in step_minus_0.05 step_0.1 gust; do \
		laddermill evaluate --scenario $$s --controllers lqr $(RUN)/best_model.zip $(RUN)/model.zip \
			--episodes 1 --out results/tethered_wing_$$s; done
