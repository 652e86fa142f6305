"""The page group of docs/wing_data.md: ``python -m laddermill_gym.derivations.derive_wing --check`` (about 4 s: the
component build-up, the mass build-up, the design checks and the pitch check about the attachment), run in a fresh
process as a user types it (its table written into a temporary folder), and its printed figures parsed."""

from __future__ import annotations

import re
import tempfile

from docsite.paper_figures import run_command

NUM = r"-?\d+(?:\.\d+)?"


def _numbers(text: str) -> list[str]:
    return re.findall(NUM, text.replace("np.float64", ""))


def _one(pattern: str, out: str) -> tuple[str, ...]:
    m = re.search(pattern, out, re.M)
    if m is None:
        raise RuntimeError(f"derive_wing --check printed nothing matching {pattern!r}:\n{out[-2000:]}")
    return m.groups()


def parse_derive_wing(out: str) -> dict:
    """The figures of ``derive_wing --check``'s output ``out``, as printed (strings): ``i_t`` [deg], ``chord`` [m],
    ``attachment`` (x, y, z [m]), ``mass`` per component (kg, x, z), ``J`` (Jxx, Jyy, Jzz, Jxz), ``model`` (its
    NAME=VALUE pairs), ``V_H``, ``V_V``, ``deps``, ``CL_max`` (value, alpha), ``CL_alpha``, ``Cm_alpha``, ``margin``
    (c, m), ``CD0``, ``LD`` (value, alpha), ``deriv`` (name -> values at 0/7/14/30/90 deg), ``free_trim``, ``kite``
    ("V6.0" -> alpha, force, lift, angle), ``elevator`` ("a7.0" -> d_e), ``de_trim`` ("de-15.0" -> alphas),
    ``tether`` ("e30" -> alpha, d_e), ``pitch`` ("v0 ascending" -> elevator, alpha, C_L, k, h_P, omega, zeta)."""
    found = {"i_t": _one(rf"^tail rigging incidence .*: ({NUM}) deg", out)[0],
             "J": _one(rf"Jxx=({NUM}) Jyy=({NUM}) Jzz=({NUM}) Jxz=({NUM})", out),
             "model": dict(re.findall(rf"([\w()+/]+)=({NUM})", _one(r"^(CLa_w=.*)$", out)[0])),
             "CL_max": _one(rf"^CL_max = ({NUM}) at alpha = ({NUM}) deg", out),
             "CD0": _one(rf"^CD at CL=0: ({NUM})", out)[0],
             "LD": _one(rf"\(L/D\)_max = ({NUM}) at alpha = ({NUM})", out),
             "free_trim": _numbers(_one(r"^free-flight trim .*alpha = \[(.*)\] deg", out)[0])[0]}
    found["chord"], found["attachment"] = _one(rf"^chord ({NUM}) m, .*attachment \[(.*)\]", out)
    found["attachment"] = _numbers(found["attachment"])
    found["V_H"], found["V_V"], found["deps"] = _one(rf"V_H .* = ({NUM}), V_V .* = ({NUM}); d eps/d alpha = ({NUM})",
                                                     out)
    found["CL_alpha"], found["Cm_alpha"], *margin = _one(rf"^aircraft CL_alpha = ({NUM}) /rad, Cm_alpha about CG = "
                                                         rf"({NUM}) /rad, static margin = ({NUM}) c = ({NUM}) m", out)
    found["margin"] = tuple(margin)
    found["mass"] = {m.group(1): m.groups()[1:] for m in
                     re.finditer(rf"^  ([a-z][a-z ]*?) +({NUM}) +({NUM}) +({NUM})$", out, re.M)}
    found["deriv"] = {m.group(1): m.group(2).split() for m in
                      re.finditer(r"^  (\w+) +at 0/7/14/30/90 deg:((?: +-?[\d.]+){5})$", out, re.M)}
    found["kite"] = {"V" + m.group(1): m.groups()[1:] for m in re.finditer(
        rf"V= *({NUM}) m/s, de=0: alpha=({NUM}) deg, cable force ({NUM}) N \(L=({NUM}) N\) at ({NUM}) deg", out)}
    found["elevator"] = {"a" + m.group(1): m.group(2) for m in re.finditer(
        rf"^elevator for kite trim at alpha= *({NUM}) deg .*: de = +({NUM}) deg", out, re.M)}
    found["de_trim"] = {"de" + m.group(1): _numbers(m.group(2)) for m in re.finditer(
        rf"^  de = +({NUM}) deg -> kite trim alpha = \[(.*)\] deg", out, re.M)}
    found["tether"] = {"e" + m.group(1): (_numbers(m.group(2))[0], m.group(3)) for m in re.finditer(
        rf"elevation (\d+) deg: trim at de=0 alpha = \[(.*?)\] deg; de for alpha=7 deg: ({NUM}) deg", out)}
    found["pitch"] = {f"{m.group(1)} {m.group(2)}": m.groups()[2:] for m in re.finditer(
        rf"^  (v\d) +(ascending|descending) +({NUM}) +({NUM}) +({NUM}) +({NUM}) +({NUM}) +({NUM}) +({NUM})$", out,
        re.M)}
    return found


def derive_wing() -> dict:
    """:func:`parse_derive_wing` of a fresh ``derive_wing --check`` run (table written to a temporary folder)."""
    with tempfile.TemporaryDirectory() as tmp:
        out = run_command(["laddermill_gym.derivations.derive_wing", "--out-dir", tmp, "--check"], 300)
    return parse_derive_wing(out)
