"""The moving-cable laddermill: Meijaard, Ockels & Schwab's examples redone (``meijaard``) and the mill's part of
``laddermill bench`` (``mill_benchmark``). May import the layers below studies and ``studies.benchmarks`` (the
timing helpers); no other topic of studies, never ``harness``."""
