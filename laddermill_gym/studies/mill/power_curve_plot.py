"""The figure of ``laddermill power-curve`` (``studies/mill/power_curve.py``): the mill's mean electrical power
against the cable speed at the paper's wind, and the best power and cable speed per wind."""

from __future__ import annotations

from pathlib import Path

__all__ = ["plot_power_curve", "grid_text"]


def plot_power_curve(path: Path, cfg, rows: list[dict], best: list[dict], paper_v0: float,
                     paper_power_w: float) -> None:
    """Power against V_c at the paper's wind ``paper_v0`` [m/s] beside its ``paper_power_w`` [W] (left); the best
    power and V_c per wind (right); ``cfg`` the run's ``power_curve.Config``, ``rows`` and ``best`` its results."""
    from matplotlib.figure import Figure

    fig = Figure(figsize=(11, 4.2))
    ax1, ax2 = fig.subplots(1, 2)
    paper = [r for r in rows if r["v0_m_s"] == paper_v0 and r["v_c_m_s"] in cfg.speeds]
    for sel, mk, lab in (([r for r in paper if r["periodic"]], "o-", "periodic"),
                         ([r for r in paper if not r["periodic"] and not r["breakdown"]], "x",
                          "not periodic (last period)")):
        if sel:
            ax1.plot([r["v_c_m_s"] for r in sel], [r["power_kW"] for r in sel], mk, label=lab)
    broke = [r for r in paper if r["breakdown"]]
    if broke:
        ax1.plot([r["v_c_m_s"] for r in broke], [0.0] * len(broke), "v", color="C3", label="broke down (at 0)")
    ax1.axhline(paper_power_w / 1e3, color="grey", ls="--", label="paper: of the order of 200 kW")
    ax1.set(xlabel="cable speed V_c [m/s]", ylabel="mean electrical power [kW]",
            title=f"{cfg.scene}, in plane, V0 = {paper_v0:g} m/s")
    ax1.legend(fontsize=8)
    okb = [b for b in best if b["power_kW"] is not None]
    over = [r for r in rows if r["periodic"] and not r["within_limit"]]
    if over:
        ax2.plot([r["v0_m_s"] for r in over], [r["power_kW"] for r in over], "x", color="grey",
                 label="periodic, tension over the limit")
    ax2.plot([b["v0_m_s"] for b in okb], [b["power_kW"] for b in okb], "o-", color="C0", label="best within the limit")
    none = [b["v0_m_s"] for b in best if b["power_kW"] is None]
    if none:
        ax2.plot(none, [0.0] * len(none), "v", color="C3", label="no periodic case within the limit")
    ax2.legend(fontsize=8)
    ax2.set(xlabel="wind speed V0 at 50 m [m/s]", ylabel="best mean power [kW]",
            title=f"best V_c per wind ({grid_text(cfg)}), tail rule '{cfg.tail}'")
    ax3 = ax2.twinx()
    ax3.plot([b["v0_m_s"] for b in okb], [b["best_v_c_m_s"] for b in okb], "s--", color="C1")
    ax3.set_ylabel("best V_c [m/s]", color="C1")
    fig.tight_layout()
    fig.savefig(path, dpi=110)


def grid_text(cfg) -> str:
    """The search per wind in words: the adaptive rule or the fixed grid's range."""
    if cfg.wind_speeds is None:
        return "adaptive V_c search"
    return f"V_c {min(cfg.wind_speeds):g}-{max(cfg.wind_speeds):g} m/s"
