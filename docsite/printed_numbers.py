"""Compare a page's quoted numbers with a command's whole printed output, by value.

A :class:`docsite.ledger_kinds.Printed` snippet agrees with an output when each number the page quotes in it
(:data:`docsite.page_numbers.NUMBER`: thousands commas and a ratio's ``x`` dropped) is some number the output prints
rounded to the quoted digits (:func:`rounds_to`; a printed 0.1145 is 0.114 or 0.115 quoted, 25.64 is 25.6, a
printed 10 is 10, never 11), or, where the page writes a unit with a prefix after it (:data:`PREFIXED`: "10 kW",
"1.8 MJ", "2.4 mm"), a thousandth, a thousand times or a millionth of one (a page's kW of a printed W, its MW of a
printed kW, its MJ of a printed J), or, where the page writes a percent sign after it (:data:`PERCENT`: "2.8 %"), a
hundred times a printed fraction (2.8e-02) or a printed percent itself (:func:`percent_marks`: "2.8 %", or a cell of
a column headed [%]), never the other way round, all within a few lines of output (:func:`missing`). Signs: a
quoted number the page writes with a sign ("-43.5 kW", "+0.7752") must have that sign printed; one it writes
without compares magnitudes (the page's "falls by 0.25" of a printed -0.252, "a drop of 46 kW"). This is looser
than a check (it does not say *which* printed number is meant), so it is used for a command's free-text lines that
no parser reads: a changed figure that no nearby printed figure matches is named. Small integers (a gust
scorecard's "8 / 9") would still find a match in almost any long output: such figures are checks of a parsed file
instead (:mod:`docsite.gust_scorecards`).

Until 2026-11-30 the rule was looser: two numbers agreed when they differed by half a unit of the quoted digits plus
half a unit of the printed ones, so a printed 10 matched a quoted 11 and a printed 0 (of "LadderMill-v0") any quoted
number below 0.5; signs were never compared. Until 2026-11-30 (the review's #18) any quoted number could also be a
thousandth, a thousand times or a millionth of a printed one, so a bare "10" matched a printed 0.0104. Until
2026-11-30 (the review's open item) a quoted percent could be any printed number or a hundred times it, so "2.8 %"
matched a printed fraction 2.8 (280 %) and a printed 0.028 % (tests/test_printed_rule.py).
"""

from __future__ import annotations

import re
from bisect import bisect_left

from docsite.page_numbers import NUMBER, prose

SCALES = (1.0, 1e-3, 1e3, 1e-6)  # a page's figure in the printed unit, or in kilo- / milli- / mega- of it
# a unit with an SI prefix written after a quoted number ("10 kW", "1.8 MJ", "2.4 mm", "0.39 ms", "4.4 MB"): only
# such a number may be a printed one in another prefix's unit; "m" alone (metres), "min", "mph" are not prefixed
PREFIXED = re.compile(r" ?[kMGmuµn](?:Wh|W|J|N|Pa|Hz|B|V|A|s|m|g|t)(?![A-Za-z])")
# the further numbers of a range or list that shares the unit written after its last one ("3.0-15.2 kN", "-3.2 to
# +1.9 MW", "14.9, 11.9 and 14.8 MJ")
# a percent sign written after a quoted number (or after the range or list it begins): a hundredth of it may be printed
# (the work-precision tables print relative errors as fractions, "2.8e-02", that the page quotes as "2.8 %")
PERCENT = re.compile(r" ?%")
PERCENT_SCALES = (1.0, 100.0)  # a printed percent as it is (:func:`percent_marks`), a printed fraction times 100
SHARED = re.compile(r"(?:-| to | and |, and |, | or | / )[-+]?\d[\d,]*(?:\.\d+)?(?:e[-+]?\d+)?(?![\w.])")
WINDOW = 60  # printed numbers a snippet's figures may spread over (a table row of a wide study prints ~20)

# a printed numeral, also one glued to a unit or letter ("1.2mm", "-30+240j"): the output side is read loosely;
# thousands commas only between groups of exactly three digits ("1,555", "12,000,000"), so "[1,2]" is 1 and 2
PRINTED = re.compile(r"[-+]?(?:\d{1,3}(?:,\d{3})+(?!\d)|\d+)(?:\.\d+)?(?:e[-+]?\d+)?")
# pytest's framing of a ``pytest -s`` group's output (:func:`own_output`): banners and header lines, the sections
# whose lines are pytest's (durations, warnings, short summary), a test file's path before the first printed line
PYTEST_FRAME = re.compile(r"=+( .* =+)?|platform .*|rootdir: .*|configfile: .*|plugins: .*|cachedir: .*|"
                          r"collect(ed|ing) .*")
PYTEST_SECTION = re.compile(r"=+ (slowest \d+ durations|warnings summary|short test summary info) =+")
# a failed test's report (the FAILURES section): its source lines and locations are pytest's; only its "E   " lines
# (the assertion's message, which the test wrote) count
PYTEST_FAILURES = re.compile(r"=+ FAILURES =+")
PYTEST_FILE = re.compile(r"^tests/[\w/]+\.py ")


def value(text: str) -> float:
    """A numeral as the page or a command writes it ("1,555", "8.7x", "3.2e-4") as a float."""
    return float(text.replace(",", "").rstrip("x"))


def unit(text: str) -> float:
    """One unit of the last digit ``text`` writes: 0.01 for 0.30, 1e5 for 2.16e7, 1 for 1,555."""
    mantissa, _, exponent = text.replace(",", "").rstrip("x").lower().partition("e")
    decimals = len(mantissa.split(".")[1]) if "." in mantissa else 0
    return 10.0 ** ((int(exponent) if exponent else 0) - decimals)


def rounds_to(p: float, pu: float, q: float, u: float) -> bool:
    """Whether a printed value ``p`` (one unit of its last digit ``pu``) rounded to the digits of a quoted ``q``
    (unit ``u``) is ``q``: where the printed digits are no finer (``pu >= u``) the two must be equal; where they are
    finer, ``p`` within half a quoted unit of ``q`` (a tie, 0.1145 to 0.114 or 0.115, either way). Equalities hold
    to 1e-12 relative (binary floats of decimal numerals)."""
    slack = 1e-12 * max(abs(p), abs(q), u)
    if pu >= u * (1.0 - 1e-9):
        return abs(p - q) <= slack
    return abs(p - q) <= 0.5 * u + slack


def agrees(quoted: str, printed: str) -> bool:
    """Whether the numeral ``printed`` (as a command writes it: "0.1145", "2.16e7", "1,555") rounded to the digits
    of ``quoted`` (as a page writes it) is ``quoted``, signs compared (:func:`rounds_to`)."""
    return rounds_to(value(printed), unit(printed), value(quoted), unit(quoted))


def template_agrees(quoted: str | None, want: str) -> bool:
    """A check's quoted text against its filled template ``want``: equal text, or for a template marked ``~`` (the
    printed value, which the page may round) :func:`agrees`; an optional group the page leaves out (None) agrees
    with a ``~`` template, and a ``~`` template that is no number (a figure the command did not print) agrees with
    nothing."""
    if not want.startswith("~"):
        return quoted == want
    if quoted is None:
        return True
    try:
        return agrees(quoted, want[1:])
    except ValueError:
        return False


def own_output(output: str) -> str:
    """``output`` without pytest's own framing where a group runs ``pytest -s``: the session header (its platform
    line's versions, "platformdirs-4.14.9"), the counts, the durations and warnings sections, the test file's path
    that starts the first printed line ("tests/test_gusts_v2.py ") and a failed test's report but for its "E " lines
    (the assertion's message), whose numbers would otherwise stand in for a figure the test did not print (a quoted
    "4 N" found in a plugin's version, 2026-12-01); other output as it is."""
    if "test session starts" not in output:
        return output
    kept, skipping, failures = [], False, False
    for line in output.splitlines():
        bare = line.strip()
        if PYTEST_SECTION.fullmatch(bare) or PYTEST_FAILURES.fullmatch(bare):
            skipping, failures = True, PYTEST_FAILURES.fullmatch(bare) is not None
        elif bare.startswith("=") and bare.endswith("="):
            skipping = failures = False
        if failures and line.startswith("E  "):
            kept.append(line[1:])
        elif not (skipping or PYTEST_FRAME.fullmatch(bare)):
            kept.append(PYTEST_FILE.sub("", line))
    return "\n".join(kept)


def missing(snippet: str, output: str) -> list[str]:
    """The numbers of ``snippet`` that ``output`` does not print near one another: each quoted number must be a
    distinct printed number rounded to the quoted digits (:func:`rounds_to`), or where a prefixed unit follows it
    (:data:`PREFIXED`) a thousandth, a thousand times or a millionth of it (its 1.8 MJ of a printed 1813 kJ or
    1813000 J), by magnitude where the page writes no sign
    (its "falls by 0.25" of a printed -0.252), within one window of :data:`WINDOW` consecutive printed numbers (a
    sentence's figures come from a few lines of output, in any order); the window that leaves the fewest unmatched
    is taken."""
    output = own_output(output)
    matches = list(PRINTED.finditer(output))
    printed = [(value(m.group()), unit(m.group())) for m in matches]
    marks = percent_marks(output, matches)
    flat = prose(snippet)
    spans = [m.span() for m in NUMBER.finditer(flat)]
    quoted = [flat[a:b] for a, b in spans]
    scales = [_scales(flat, _unit_at(flat, b)) for _, b in spans]
    hits = [[i for i, (p, pu) in enumerate(printed)
             if _hit(p, pu, text, _percent(factors, marks[i]))]
            for text, factors in zip(quoted, scales, strict=True)]
    best = list(quoted)
    for start in sorted({i for found in hits for i in found}):  # a best window can start at a matched number
        near = [found[bisect_left(found, start):bisect_left(found, start + WINDOW)] for found in hits]
        matched = _matching(near)
        lost = [text for k, text in enumerate(quoted) if k not in matched]
        if len(lost) < len(best):
            best = lost
        if not best:
            break
    return best


def _unit_at(flat: str, end: int) -> int:
    """Where the unit of the number ending at ``end`` in ``flat`` starts: after the range or list it begins
    (:data:`SHARED`), if any."""
    m = SHARED.match(flat, end)
    while m:
        end = m.end()
        m = SHARED.match(flat, end)
    return end


def _scales(flat: str, at: int) -> tuple[float, ...]:
    """The factors a printed value may be multiplied by to be the quoted number whose unit starts at ``at`` in
    ``flat``: :data:`SCALES` after a prefixed unit, :data:`PERCENT_SCALES` after a percent sign, else 1 alone."""
    if PREFIXED.match(flat, at):
        return SCALES
    return PERCENT_SCALES if PERCENT.match(flat, at) else SCALES[:1]


def percent_marks(output: str, found: list[re.Match]) -> list[bool]:
    """Per printed numeral (``found``: :data:`PRINTED`'s matches in ``output``) whether the output marks it a
    percent: a percent sign right after it ("-9.6 %", "2.8%"), or a cell of a Markdown table's body ("| 46.7 |")
    whose header cell in the same column has one ("| capacity factor [%] |"). Any other printed number is read as a
    fraction by a quoted percent."""
    header: dict[int, list[str]] = {}  # a table body row's line start -> its table's header cells
    cells: list[str] = []
    start = 0
    for line in output.split("\n"):  # line starts as rfind("\n") finds them below (not splitlines: "\r")
        row = line.strip()
        if not row.startswith("|"):
            cells = []
        elif not cells:
            cells = row.split("|")
        else:
            header[start] = cells
        start += len(line) + 1
    marks = []
    for m in found:
        line = output.rfind("\n", 0, m.start()) + 1
        column = output.count("|", line, m.start())
        head = header.get(line, [])
        marks.append(bool(PERCENT.match(output, m.end())) or (column < len(head) and "%" in head[column]))
    return marks


def _percent(factors: tuple[float, ...], marked: bool) -> tuple[float, ...]:
    """``factors`` for one printed number: after a quoted percent (:data:`PERCENT_SCALES`) 1 for a printed percent
    (``marked``, :func:`percent_marks`) and 100 for a printed fraction, never both; other factors as they are."""
    if factors is not PERCENT_SCALES:
        return factors
    return PERCENT_SCALES[:1] if marked else PERCENT_SCALES[1:]


def _hit(p: float, pu: float, text: str, factors: tuple[float, ...]) -> bool:
    """Whether a printed value ``p`` (unit ``pu``) times one of ``factors`` (:func:`_scales`: 1, or a thousandth,
    thousand times or millionth after a prefixed unit, or a hundred times before a percent sign) is the quoted
    numeral ``text``; by magnitude where ``text`` has no sign."""
    q, u = value(text), unit(text)
    if text[0] not in "+-":  # no sign on the page: magnitudes
        p, q = abs(p), abs(q)
    return any(rounds_to(f * p, f * pu, q, u) for f in factors)


def _matching(candidates: list[list[int]]) -> set[int]:
    """The quoted numbers (indices into ``candidates``, each a list of printed indices it may be) that a largest
    one-to-one assignment to printed numbers covers (augmenting paths: a quoted 0.01 that a printed 8.7e-3 would
    match no longer takes the 8.7 a later quoted 8.7 needs)."""
    owner: dict[int, int] = {}

    def assign(k: int, seen: set) -> bool:
        for i in candidates[k]:
            if i not in seen:
                seen.add(i)
                if i not in owner or assign(owner[i], seen):
                    owner[i] = k
                    return True
        return False

    for k in range(len(candidates)):
        assign(k, set())
    return set(owner.values())


def printed_differences(page: str, entries: tuple, measured: dict) -> list[str]:
    """Each Printed snippet of ``page`` (docs file name) whose group was measured (its figures in ``measured``, the
    output under ``"printed"``) and quotes a number the output does not print; [] when all agree. An entry of one
    profile (``Printed.cpu``) is compared only with a run on that profile (the group's ``"cpu"``)."""
    bad = []
    for entry in entries:
        figures = measured.get(entry.group)
        if not isinstance(figures, dict) or "printed" not in figures:
            continue
        if getattr(entry, "cpu", "") and entry.cpu != figures.get("cpu"):
            continue
        for snippet in entry.snippets:
            lost = missing(snippet, figures["printed"])
            if lost:
                bad.append(f"docs/{page}: {entry.group} printed none of {lost} in {snippet!r}")
    return bad
