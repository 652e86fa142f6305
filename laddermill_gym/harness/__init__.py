"""The controller harness's commands: ``laddermill train`` (Stable-Baselines3 from configs/agents/*.yaml),
``laddermill evaluate`` (any controller on seeded episodes) and ``laddermill lqr`` (LQR design report). Top layer:
may import everything below it (``studies.parallel``, the executor, and ``studies.commands``, a command's parser,
included); the repository's ``agents/`` scripts are thin entry points to these modules."""
