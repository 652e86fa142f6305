"""Every number in a config has a unit (the project's standard: "Every number in a config has a unit and a source").

Every ``configs/**/*.yaml`` is read line by line (comments are the subject, so no YAML round trip). A *number line* is
a ``key: value`` or ``- value`` line whose value, read with ``yaml.safe_load``, holds an int or a float: a scalar, a
list of them or a flow mapping such as ``{type: SpeedStep, step: 0.2, time: 5.0}``. A flow collection may span lines
and is then one value. Booleans, null and strings (quoted numbers included) are not numbers. A number line passes when

1. its trailing comment *starts* with a unit in brackets, ``# [m/s] source or reason``. A unit is ``[-]``
   (dimensionless: ratios, weights, coefficients, and counts of things: copies, episodes, wings, layer widths),
   ``[%]``, or brackets holding a letter (``[m]``, ``[1/s]``, ``[kg/m^3]``, ``[steps]``, ``[rad], [s]`` for a
   flow mapping); a numeric list such as ``[0, 1]`` is not a unit. A value over several lines may carry the comment
   on any of them; or
2. it lies in the block of a parent key whose comment starts with ``(all [unit])``, e.g.
   ``ground_points:   # (all [m]) both cable ends ...``: every number below that key, to the end of its block
   (deeper lines, and ``-`` items at the key's own indent), has that unit unless its own line gives one.

Exempt: the keys ``seed``, ``seeds`` and ``version``, which name a random stream or a file format, not a quantity; and
the shipped gust suites (``configs/benchmarks/<name>.yaml`` for the names in ``gust_suite.SHIPPED_SHA256``), whose
bytes are pinned by SHA-256 and so cannot take a comment: a new suite is checked. Units only: the source may stand in
a block comment above a group (the standard allows it), which a line reader cannot tell from prose.
"""

from __future__ import annotations

import re
from pathlib import Path

import yaml

from laddermill_gym.studies.gusts.gust_suite import SHIPPED_SHA256

CONFIGS = Path(__file__).resolve().parents[1] / "configs"
EXEMPT_KEYS = {"seed", "seeds", "version"}
KEY = re.compile(r"^(?P<item>-\s+)?(?P<key>\"[^\"]*\"|'[^']*'|[^\s#'\"{}\[\],:][^#{}\[\],:]*?)"
                 r"\s*:(?:\s+|$)(?P<val>.*)$")
ITEM = re.compile(r"^-\s+(?P<val>.*)$")
UNIT = r"\[(?:-|%|[^\[\]]*[A-Za-z][^\[\]]*)\]"
OWN_UNIT = re.compile(UNIT)
ALL_UNIT = re.compile(rf"\(all {UNIT}\)")


def split_comment(line: str) -> tuple[str, str]:
    """(code, comment) of one line: the comment starts at a ``#`` outside quotes after a blank or at the start."""
    quote = None
    for i, c in enumerate(line):
        if quote:
            quote = None if c == quote else quote
        elif c in "\"'" and (i == 0 or line[i - 1] in " [{,:-"):
            quote = c
        elif c == "#" and (i == 0 or line[i - 1] in " \t"):
            return line[:i].rstrip(), line[i + 1:].strip()
    return line.rstrip(), ""


def count_numbers(value) -> int:
    """How many ints and floats (not booleans) ``value`` holds, through lists and mappings."""
    if isinstance(value, bool):
        return 0
    if isinstance(value, int | float):
        return 1
    if isinstance(value, dict):
        return sum(count_numbers(v) for v in value.values())
    if isinstance(value, list):
        return sum(count_numbers(v) for v in value)
    return 0


def check_lines(lines: list[str]) -> tuple[int, list[tuple[int, str, str]]]:
    """(numbers checked, failures as (line number, key, why)) of one YAML file's lines under the rules above."""
    parsed = [split_comment(line) for line in lines]
    checked, failures, covered = 0, [], []  # covered: a stack of (indent, is a marker) of open parent blocks
    i = 0
    while i < len(parsed):
        code, comment = parsed[i]
        start, i = i, i + 1
        if not code.strip():
            continue
        indent, body = len(code) - len(code.lstrip()), code.strip()
        match = KEY.match(body) or ITEM.match(body)
        if match is None:
            failures.append((start + 1, "?", f"not a key or list line: {body!r}"))
            continue
        is_item = body.startswith("- ")
        key = (match.groupdict().get("key") or "-").strip("\"'")
        while covered and (indent < covered[-1] or (indent == covered[-1] and not is_item)):
            covered.pop()
        value_text = match.group("val")
        if not value_text:  # a parent: its block is covered when its comment starts with (all [unit])
            if ALL_UNIT.match(comment):  # a list item's key ("- key:"): its block is that key's, not the item's
                covered.append(indent + 2 if is_item and match.groupdict().get("key") else indent)
            continue
        comments = [comment]
        while True:  # a flow collection over several lines: join them until the value parses
            try:
                value = yaml.safe_load(value_text)
                break
            except yaml.YAMLError:
                if i >= len(parsed) or i - start > 20:
                    failures.append((start + 1, key, "value does not parse"))
                    value = None
                    break
                value_text += " " + parsed[i][0].strip()
                comments.append(parsed[i][1])
                i += 1
        numbers = count_numbers(value)
        if not numbers or key in EXEMPT_KEYS:
            continue
        checked += numbers
        if not covered and not any(OWN_UNIT.match(c) for c in comments):
            failures.append((start + 1, key, "no [unit] at the start of its comment"))
    return checked, failures


def config_files() -> list[Path]:
    """Every YAML config but the frozen gust suites."""
    frozen = {CONFIGS / "benchmarks" / f"{name}.yaml" for name in SHIPPED_SHA256}
    return [p for p in sorted(CONFIGS.rglob("*.yaml")) if p not in frozen]


def test_every_number_has_a_unit():
    files = config_files()
    total, report = 0, []
    for path in files:
        checked, failures = check_lines(path.read_text(encoding="utf-8").splitlines())
        total += checked
        report += [f"{path.relative_to(CONFIGS.parent)}:{n}:{key}: {why}" for n, key, why in failures]
    assert not report, f"{len(report)} of {total} numbers lack a unit:\n" + "\n".join(report)
    assert len(files) > 40 and total > 1000, (len(files), total)  # the walk reached the configs


def test_the_rules_flag_what_they_should():
    lines = ["a: 1.0            # [m] ok", "b: 2.0            # a reason without unit", "c: [0.0, 1.0]     # [0, 1]",
             "d: true", "seed: 3", "e: {x: 1.0, y: z}", "f:                # (all [deg]) each child",
             "  g: 1.0", "  - 2.0", "  h: {x: [1.0,", "        2.0]}", "i: 3               # [-] count",
             "j:                # [m] not a marker", "  k: 4", "l: '5'", "m: [1,", "    2]            # [s]"]
    checked, failures = check_lines(lines)
    assert [(n, key) for n, key, _ in failures] == [(2, "b"), (3, "c"), (6, "e"), (14, "k")]
    assert checked == 13
    # a marker on a list item's key covers that key's block, not the items after it (they passed unchecked)
    items = ["points:", "- xyz:          # (all [m]) corners", "    a: 1.0", "  other: 2.0", "- mass: 5.0",
             "- speed: 3.0     # [m/s]"]
    checked, failures = check_lines(items)
    assert [(n, key) for n, key, _ in failures] == [(4, "other"), (5, "mass")] and checked == 4
