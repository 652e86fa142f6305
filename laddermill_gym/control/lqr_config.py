"""Configuration of the lateral LQR (``configs/agents/lqr_*.yaml``): the lateral state and inputs of one wing,
:class:`LQRConfig` and its loader, and Bryson's-rule weights."""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from laddermill_gym.model.configio import CONFIG_DIR, config_path, find_config, read_yaml, shipped_names

#: Lateral state of one wing (deviation from trim) and its units: m, m/s, rad, rad, rad/s, rad/s.
LATERAL_STATE_NAMES: tuple[str, ...] = ("y", "vy", "phi", "psi", "p", "r")
#: Lateral inputs of one wing [rad].
LATERAL_INPUT_NAMES: tuple[str, ...] = ("rudder", "aileron")

DEFAULT_CONFIG = CONFIG_DIR / "agents" / "lqr_tethered_wing.yaml"
DEFAULT_CHAIN_CONFIG = CONFIG_DIR / "agents" / "lqr_ladder_chain.yaml"

_MAX_STATE_KEYS = (("y", 1.0), ("vy", 1.0), ("phi_deg", math.pi / 180), ("psi_deg", math.pi / 180),
                   ("p_deg_s", math.pi / 180), ("r_deg_s", math.pi / 180))


# ------------------------------------------------------------------------------------ configuration
@dataclass(frozen=True)
class LQRConfig:
    """A lateral LQR design (``configs/agents/lqr_*.yaml``).

    Attributes
    ----------
    file : Path
    scene : str                   the scene as the design loads it: a shipped scene's bare name, or the YAML's absolute
                                  path (a relative path resolved once against the config's folder, as the loader
                                  checks it, so every design reads the file the loader checked)
    elements_per_piece : int      cable elements per piece (1 = the environments' model; a single-wing design, the
                                  mill's and a centralised chain's need 1: cable nodes add lateral states no
                                  controller of the environments observes)
    control_period : float        [s] zero-order-hold period of the controller
    max_state : ndarray (6,)      largest acceptable deviations of (y [m], vy [m/s], phi [rad], psi [rad],
                                  p [rad/s], r [rad/s]) (Bryson's rule)
    max_input : ndarray (2,)      largest acceptable (rudder, aileron) deflection from trim [rad]
    structure : str               chains and the mill: "decentralised" (each wing's gain from its own lateral block)
                                  or "centralised" (one gain on the full coupled lateral model); a single wing:
                                  "decentralised" (its one gain; "centralised" is refused)
    design_model : str            the moving mill (``control.mill_lqr``): "transfer_phase" (the lateral model at
                                  the operating point's phase, just after a transfer) or "period_mean" (the mean of
                                  the models at the checked phases of the orbit); other systems: "transfer_phase"
                                  (their one trim; "period_mean" is refused)
    """

    file: Path
    scene: str
    elements_per_piece: int
    control_period: float
    max_state: np.ndarray
    max_input: np.ndarray
    structure: str = "decentralised"
    design_model: str = "transfer_phase"


STRUCTURES: tuple[str, ...] = ("decentralised", "centralised")
DESIGN_MODELS: tuple[str, ...] = ("transfer_phase", "period_mean")


#: Upper bounds of the Bryson's-rule limits (largest acceptable deviations) and why (the craft's LQR config too).
MAX_STATE_BOUNDS = {"y": (1e4, "m: beyond the cable's reach"), "vy": (150.0, "m/s: the fastest wind (bounds.py)"),
                     "phi_deg": (180.0, "deg: an angle"), "psi_deg": (180.0, "deg: an angle"),
                     "p_deg_s": (36000.0, "deg/s: 100 turns per second"),
                     "r_deg_s": (36000.0, "deg/s: 100 turns per second")}
#: Bounds of the control period [s] and of a Bryson's-rule input limit [deg] (the craft's LQR config too).
CONTROL_PERIOD_BOUND = dict(high=10.0, why="s: the wings' lateral mode has a period of about 15 s")
MAX_INPUT_BOUND = dict(high=90.0, why="deg: a control-surface deflection")


def _scene_reference(s, scene: str, folder: Path) -> tuple[str, dict]:
    """(the scene as the design loads it, the scene file's top-level fields): ``scene`` resolved once against the
    config's ``folder`` (a shipped scene's bare name stays a name, a file becomes its absolute path); ConfigError
    naming the field when there is no such file."""
    path = config_path("scenes", scene, folder)
    if not path.is_file():
        raise s.error("scene", scene, f"no such scene file (a bare name is one of the shipped scenes: "
                                      f"{', '.join(shipped_names('scenes'))})")
    shipped = path == CONFIG_DIR / "scenes" / f"{scene}.yaml"
    data = read_yaml(path).data
    return (scene if shipped else str(path.resolve())), (data if isinstance(data, dict) else {})


def _check_design_fields(s, scene: str, data: dict, epp: int, structure: str, design_model: str) -> None:
    """ConfigError naming the field where the config's scene's design cannot use it: more than one element per piece
    for a single wing, the mill or a centralised chain (cable nodes add lateral states the environments' controllers
    do not observe), ``structure: centralised`` for a single wing, ``design_model: period_mean`` off the mill."""
    chain = data.get("chain")
    n_wings = chain.get("n_wings") if isinstance(chain, dict) else None
    mill = "station" in data
    single = n_wings == 1 and not mill
    if epp > 1 and (single or mill or structure == "centralised"):
        what = ("a single-wing design" if single else "the mill's design" if mill else "a centralised design")
        raise s.error("elements_per_piece", epp, f"{what} (scene {scene}) observes the wings only: cable nodes "
                      "(more than one element per piece) add lateral states that no controller of the environments "
                      "observes; use elements_per_piece = 1")
    if single and structure != "decentralised":
        raise s.error("structure", structure, f"scene {scene} has one wing: its design is one gain on the wing's own "
                      "lateral model (the field is for chains and the mill)")
    if not mill and design_model != "transfer_phase":
        raise s.error("design_model", design_model, f"scene {scene} is not a moving-cable mill: its design has one "
                      "trim (the field is for the mill's orbit, control.mill_lqr)")


def load_lqr_config(path: str | Path = DEFAULT_CONFIG) -> LQRConfig:
    """Read an LQR config YAML (``path``: a file or the bare name of a shipped one, ``lqr_tethered_wing``; strict:
    unknown keys, a missing scene file, non-positive or out-of-range limits and fields the scene's design cannot use
    raise ConfigError naming the field). A scene path is resolved once, against the config's folder."""
    path = find_config("agents", path, "config")
    s = read_yaml(path)
    scene, scene_data = _scene_reference(s, s.text("scene"), path.parent)
    epp = s.number("elements_per_piece", integer=True, positive=True, high=1000,
                   why="the design linearises the whole model densely")
    period = s.number("control_period", positive=True, **CONTROL_PERIOD_BOUND)
    ms = s.section("max_state")
    max_state = np.array([ms.number(k, positive=True, high=MAX_STATE_BOUNDS[k][0], why=MAX_STATE_BOUNDS[k][1])
                          * scale for k, scale in _MAX_STATE_KEYS])
    ms.done()
    mi = s.section("max_input_deg")
    max_input = np.radians([mi.number(k, positive=True, **MAX_INPUT_BOUND) for k in LATERAL_INPUT_NAMES])
    mi.done()
    structure = s.text("structure", "decentralised", choices=STRUCTURES)
    design_model = s.text("design_model", "transfer_phase", choices=DESIGN_MODELS)
    s.done()
    _check_design_fields(s, scene, scene_data, epp, structure, design_model)
    return LQRConfig(file=Path(path), scene=scene, elements_per_piece=epp, control_period=period,
                     max_state=max_state, max_input=max_input, structure=structure, design_model=design_model)


def bryson_weights(max_state: np.ndarray, max_input: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Bryson's rule: Q = diag(1 / max_state^2), R = diag(1 / max_input^2)."""
    return np.diag(1.0 / np.asarray(max_state, float) ** 2), np.diag(1.0 / np.asarray(max_input, float) ** 2)
