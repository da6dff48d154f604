#!/usr/bin/env python3
"""Consistency checks between the documentation, the input decks and the tests' stored values.

    check_docs.py --root DIR [--check decks,main-job,main-numbers]   (default: these three)
    check_docs.py --root DIR --check issue-numbers

Checks (each finding is printed as FILE:LINE: message; exit status 1 if there is any):

decks          every input/*.xml: a number of cycles stated in a comment ("16 Dorfler cycles")
               must equal the deck's Adaptivity/Cycles, unless the comment names that count as a
               setting ("Adaptivity/Cycles = 0"); a final DOF count ("... to 49021 DOFs") or a
               final eta ("eta 3.78e-3") stated in a comment must agree with the values that
               the tests store for a run of the deck as shipped (an sc_run_test of
               tests/CMakeLists.txt with that DECK and no SETS; its CHECKS or its EXPECTED file in
               tests/expected), to the precision the comment gives. A test of the deck as
               shipped whose cycle count (size:/cycles) is not Cycles + 1 is reported too.
               Decks that no test runs as shipped but whose run as shipped is a committed study
               CSV (STUDY_RUNS: the 3D Hertz decks, run by docs/adaptivity/hertz3d_study.py with
               only Adaptivity/Cycles raised, so that its row of cycle Cycles is the deck's last
               cycle) are checked against that row; there a stated range "5-8 Newton steps per
               cycle" must also hold the CSV's newton_steps of cycles 0 to Cycles.
main-job       README.md and docs/user-guide.md: a sentence about the main job (it names "main
               job" or hertz2d.xml) that states a number of cycles, and a progress line
               "cycle N/M" in a section about the main job, must agree with the Adaptivity/Cycles
               of input/hertz2d.xml; the user guide's table of shipped decks must give each deck's
               Marking and Cycles.
main-numbers   the numbers README.md quotes for the main job against the values that the test
               run_hertz2d_main_job stores (tests/expected/hertz2d_main_job.json, which that test
               asserts against a run of input/hertz2d.xml at 1 and 4 ranks): each row of the
               table under the heading about the main job that names summary.json keys in
               backquotes (`dofs.total`, `contact.force[1]`) and gives one number per key (text in
               parentheses is a remark and not read), and in the progress lines of the main job's
               last cycle ("cycle 16/16") the DOFs, eta and its parts, the force, half-width, peak
               pressure, stick zone, point counts, Newton steps and element count. A quoted
               number must round to the stored value at the precision it is written with; a
               quoted quantity that the test does not store is a finding too, so that every
               number of the main job's documented result is one the test asserts.
issue-numbers  no file under docs/, packages/, apps/, tests/ or README.md cites an issue tracker
               number (the word issue, a space, a hash sign and a digit): the repository is read
               without the tracker.

Only the Python 3 standard library is used.
"""

import argparse
import csv
import json
import os
import re
import sys
import xml.etree.ElementTree as ET

# "16 cycles", "16 Dorfler cycles", "20 adaptive cycles"; the plural only ("17 cycle entries" is
# not a cycle count).
CYCLES = re.compile(r"(?<![\w./=-])(\d+)\s+(?:(?:more|further|Dörfler|Dorfler|adaptive|uniform|"
                    r"refinement|Dörfler refinement|Dorfler refinement)\s+)?cycles\b", re.I)
# Counts that are not the run's length: "the last 8 cycles", "over the first 12 cycles".
NOT_A_COUNT = re.compile(r"(?:last|first|every|each|per|previous|next|other)\s+$", re.I)
SETTING = re.compile(r"Cycles\s*=\s*(\d+)")
PROGRESS = re.compile(r"\bcycle\s+(\d+)/(\d+)\b")
# "to 49021 DOFs", "to about 180k DOFs", "to 49,021 DOFs": the last cycle's DOFs.
FINAL_DOFS = re.compile(r"\bto\s+(about\s+)?(\d[\d,]*(?:\.\d+)?)\s*(k|M)?\s+DOFs\b")
ETA = re.compile(r"\beta\s*(?:=\s*)?(\d+(?:\.\d+)?)\s*[eE]\s*([-−]?\d+)")
NEWTON_RANGE = re.compile(r"\b(\d+)\s*[-–]\s*(\d+)\s+(?:semismooth\s+)?Newton steps per cycle")
# Decks whose run as shipped (with more cycles) is a committed study CSV: deck -> CSV. The study
# (docs/adaptivity/hertz3d_study.py, RUNS) changes only Adaptivity/Cycles, and a run's first
# cycles do not depend on how many follow.
STUDY_RUNS = {"hertz3d.xml": "docs/adaptivity/hertz3d_coulomb_adaptive.csv",
              "hertz3d_frictionless.xml": "docs/adaptivity/hertz3d_frictionless_adaptive.csv"}
ISSUE = re.compile(r"\bissues?\s#\d+", re.I)
MAIN_JOB = re.compile(r"main job|(?<![\w_])hertz2d\.xml", re.I)

ISSUE_SCOPE = ["README.md", "docs", "packages", "apps", "tests"]
TEXT_SUFFIXES = {".md", ".txt", ".py", ".cpp", ".hpp", ".h", ".c", ".cmake", ".xml", ".sh",
                 ".csv", ".log", ".json", ".in", ".cfg", ".msh", ".geo"}


class Findings:
    def __init__(self, root):
        self.root = root
        self.items = []

    def add(self, path, line, message):
        rel = os.path.relpath(path, self.root)
        self.items.append(f"{rel}:{line}: {message}")


def line_of(text, offset):
    return text.count("\n", 0, offset) + 1


# --- input decks ---------------------------------------------------------------------------------

def deck_cycles(path):
    """Adaptivity/Cycles of a deck (0, the default, when the deck does not set it)."""
    root = ET.parse(path).getroot()
    for plist in root.iter("ParameterList"):
        if plist.get("name") == "Adaptivity":
            for p in plist.findall("Parameter"):
                if p.get("name") == "Cycles":
                    return int(p.get("value"))
    return 0


def expected_checks(path):
    """{check key: value text} of a tests/expected file, in the form of the CHECKS strings
    ("near:/pointer": "value:tolerance", "eq:/pointer": "value", ...)."""
    checks = {}
    if not os.path.exists(path):
        return checks
    text = lambda v: v if isinstance(v, str) else json.dumps(v)
    for c in json.load(open(path, encoding="utf-8")).get("checks", []):
        kind, pointer = c.get("check"), c.get("pointer")
        if kind == "near":
            checks[f"near:{pointer}"] = f"{text(c['value'])}:{text(c['tolerance'])}"
        elif kind in ("eq", "ge", "le", "gt", "size"):
            checks[f"{kind}:{pointer}"] = text(c["value"])
    return checks


def stored_runs(root):
    """{deck file name: [(test name, line, {check key: value text})]} for the sc_run_test calls of
    tests/CMakeLists.txt that run a deck as shipped (no SETS)."""
    path = os.path.join(root, "tests", "CMakeLists.txt")
    runs = {}
    if not os.path.exists(path):
        return runs
    text = open(path, encoding="utf-8").read()
    for m in re.finditer(r"^sc_run_test\((\w+)(.*?)\)\s*$", text, re.M | re.S):
        body = m.group(2)
        deck = re.search(r"DECK\s+\$\{SC_INPUT\}/([\w.]+)", body)
        if not deck or re.search(r"\bSETS\b", body):
            continue
        checks = {}
        cm = re.search(r'CHECKS\s+"([^"]*)"', body)
        for item in (cm.group(1).split("|") if cm else []):
            if "=" in item:
                key, value = item.split("=", 1)
                checks[key] = value
        em = re.search(r"EXPECTED\s+([\w.]+)", body)
        if em:  # the stored values in tests/expected/<file> (tests/expected/README.md)
            checks.update(expected_checks(os.path.join(root, "tests", "expected", em.group(1))))
        runs.setdefault(deck.group(1), []).append((m.group(1), line_of(text, m.start()), checks))
    return runs


def precision_tolerance(number_text, scale=1.0):
    """Half a unit of the last digit given."""
    digits = number_text.replace(",", "")
    decimals = len(digits.split(".")[1]) if "." in digits else 0
    return 0.5 * 10.0 ** (-decimals) * scale


def check_decks(root, findings):
    runs = stored_runs(root)
    input_dir = os.path.join(root, "input")
    for name in sorted(os.listdir(input_dir)) if os.path.isdir(input_dir) else []:
        if not name.endswith(".xml"):
            continue
        path = os.path.join(input_dir, name)
        text = open(path, encoding="utf-8").read()
        try:
            cycles = deck_cycles(path)
        except (ET.ParseError, ValueError) as e:
            findings.add(path, 1, f"cannot read Adaptivity/Cycles: {e}")
            continue
        final_dofs = final_eta = None
        for test, tline, checks in runs.get(name, []):
            size = checks.get("size:/cycles")
            if size is not None and int(size) != cycles + 1:
                findings.add(os.path.join(root, "tests", "CMakeLists.txt"), tline,
                             f"{test} runs {name} as shipped and expects {size} cycle entries, "
                             f"but the deck's Adaptivity/Cycles = {cycles} gives {cycles + 1}")
                continue
            if "eq:/cycles/-1/dofs/total" in checks:
                final_dofs = (int(checks["eq:/cycles/-1/dofs/total"]), test)
            if "near:/cycles/-1/eta/total" in checks:
                final_eta = (float(checks["near:/cycles/-1/eta/total"].split(":")[0]), test)
        newton = None
        study = os.path.join(root, STUDY_RUNS[name]) if name in STUDY_RUNS else None
        if final_dofs is None and study and os.path.exists(study):
            with open(study, newline="", encoding="utf-8") as f:
                rows = [r for r in csv.DictReader(f) if int(r["cycle"]) <= cycles]
            if rows and int(rows[-1]["cycle"]) == cycles:
                source = os.path.relpath(study, root)
                final_dofs = (int(rows[-1]["dofs"]), source)
                final_eta = (float(rows[-1]["eta"]), source)
                steps = [int(r["newton_steps"]) for r in rows]
                newton = (min(steps), max(steps), source)
        for cm in re.finditer(r"<!--(.*?)-->", text, re.S):
            comment, base = cm.group(1), cm.start(1)
            for m in NEWTON_RANGE.finditer(comment):
                if newton and (int(m.group(1)), int(m.group(2))) != newton[:2]:
                    findings.add(path, line_of(text, base + m.start()),
                                 f'comment says "{m.group(0)}" but {newton[2]} (the deck as shipped) '
                                 f"takes {newton[0]}-{newton[1]} in cycles 0 to {cycles}")
            settings = {int(s) for s in SETTING.findall(comment)}
            for m in CYCLES.finditer(comment):
                n = int(m.group(1))
                if NOT_A_COUNT.search(comment[:m.start()]) or n == cycles or n in settings:
                    continue
                findings.add(path, line_of(text, base + m.start()),
                             f'comment says "{m.group(0)}" but Adaptivity/Cycles = {cycles}')
            for m in FINAL_DOFS.finditer(comment):
                if final_dofs is None:
                    continue  # no stored run of the deck as shipped to compare with
                about, number, unit = m.group(1), m.group(2), m.group(3)
                scale = {"k": 1e3, "M": 1e6}.get(unit, 1.0)
                value = float(number.replace(",", "")) * scale
                tol = max(precision_tolerance(number, scale), 0.1 * value if about else 0.0)
                if abs(value - final_dofs[0]) > tol:
                    findings.add(path, line_of(text, base + m.start()),
                                 f'comment says "{m.group(0)}" but {final_dofs[1]} has '
                                 f"{final_dofs[0]} DOFs in the last cycle (Adaptivity/Cycles = {cycles})")
            for m in ETA.finditer(comment):
                if final_eta is None:
                    continue
                mantissa, exponent = m.group(1), int(m.group(2).replace("−", "-"))
                value = float(mantissa) * 10.0 ** exponent
                tol = precision_tolerance(mantissa, 10.0 ** exponent)
                if abs(value - final_eta[0]) > tol * (1 + 1e-9):
                    findings.add(path, line_of(text, base + m.start()),
                                 f'comment says "{m.group(0)}" but {final_eta[1]} has eta = '
                                 f"{final_eta[0]:.4g} in the last cycle")


# --- the main job in README.md and docs/user-guide.md --------------------------------------------

def sentences(text):
    """(offset, unit, in_code, heading) of a Markdown text, each unit a substring of the text that
    starts at offset: each line of a code block or a table, otherwise each sentence of a
    paragraph."""
    units = []
    heading = ""
    offset = 0
    pstart, plen = None, 0
    fenced = False

    def flush():
        nonlocal pstart
        if pstart is None:
            return
        para = text[pstart:pstart + plen]
        begin = 0
        # sentence ends: ". " before a capital letter, a backquote, a bracket or emphasis
        for m in re.finditer(r"(?<=[.!?])\s+(?=[A-Z`(*])", para):
            units.append((pstart + begin, para[begin:m.start()], False, heading))
            begin = m.end()
        units.append((pstart + begin, para[begin:], False, heading))
        pstart = None

    for line in text.splitlines(keepends=True):
        stripped = line.strip()
        if stripped.startswith("```"):
            flush()
            fenced = not fenced
        elif fenced or (line.startswith("    ") and pstart is None and stripped):
            units.append((offset + len(line) - len(line.lstrip()), stripped, True, heading))
        elif stripped.startswith("#"):
            flush()
            heading = stripped
        elif stripped.startswith("|"):
            flush()
            units.append((offset, line.rstrip("\n"), False, heading))
        elif not stripped:
            flush()
        else:
            if pstart is None:
                pstart, plen = offset, 0
            plen += len(line)
        offset += len(line)
    flush()
    return units


def check_main_job(root, findings):
    deck = os.path.join(root, "input", "hertz2d.xml")
    if not os.path.exists(deck):
        findings.add(deck, 1, "the main job's deck is missing")
        return
    cycles = deck_cycles(deck)
    for rel in ("README.md", os.path.join("docs", "user-guide.md")):
        path = os.path.join(root, rel)
        if not os.path.exists(path):
            continue
        text = open(path, encoding="utf-8").read()
        for offset, unit, in_code, heading in sentences(text):
            about_main = bool(MAIN_JOB.search(unit)) or (in_code and "main job" in heading.lower())
            if not about_main:
                continue
            settings = {int(s) for s in SETTING.findall(unit)}
            for m in CYCLES.finditer(unit):
                n = int(m.group(1))
                if NOT_A_COUNT.search(unit[:m.start()]) or n == cycles or n in settings:
                    continue
                findings.add(path, line_of(text, offset + m.start()),
                             f'says "{m.group(0)}" about the main job, but input/hertz2d.xml has '
                             f"Adaptivity/Cycles = {cycles}")
            if in_code:
                for m in PROGRESS.finditer(unit):
                    if int(m.group(2)) != cycles or int(m.group(1)) > cycles:
                        findings.add(path, line_of(text, offset + m.start()),
                                     f'progress line "{m.group(0)}" of the main job, but '
                                     f"input/hertz2d.xml has Adaptivity/Cycles = {cycles}")
        if rel.endswith("user-guide.md"):
            check_deck_table(root, path, text, findings)


def deck_marking(path):
    root = ET.parse(path).getroot()
    for plist in root.iter("ParameterList"):
        if plist.get("name") == "Adaptivity":
            for p in plist.findall("Parameter"):
                if p.get("name") == "Marking":
                    return p.get("value")
    return "Dorfler"


def check_deck_table(root, path, text, findings):
    """Rows "| `a.xml`, `b.xml` | ... | Marking, N / Marking, M |" of the user guide's deck table."""
    for offset, unit, in_code, heading in sentences(text):
        if in_code or not unit.startswith("|"):
            continue
        cells = [c.strip() for c in unit.strip("|").split("|")]
        decks = re.findall(r"`([\w.]+\.xml)`", cells[0]) if cells else []
        if not decks or len(cells) < 3:
            continue
        stated = re.findall(r"(Dorfler|Dörfler|Maximum|Uniform),\s*(\d+)", cells[-1])
        if len(stated) != len(decks):
            continue
        for deck_name, (marking, n) in zip(decks, stated):
            deck_path = os.path.join(root, "input", deck_name)
            if not os.path.exists(deck_path):
                findings.add(path, line_of(text, offset), f"{deck_name} is not in input/")
                continue
            actual = (deck_marking(deck_path), deck_cycles(deck_path))
            if (marking.replace("ö", "o"), int(n)) != actual:
                findings.add(path, line_of(text, offset),
                             f"the table gives {deck_name} as {marking}, {n}; the deck has "
                             f"Marking = {actual[0]}, Cycles = {actual[1]}")


# --- the main job's numbers in README.md against run_hertz2d_main_job's stored values ----------

MAIN_TEST = "run_hertz2d_main_job"
SUPERSCRIPT = str.maketrans("⁻⁰¹²³⁴⁵⁶⁷⁸⁹", "-0123456789")
# 49,021  0.07548  3.779·10⁻³  4.96757e-07  108.125
NUMBER = re.compile(r"(?<![\w.])[-−]?(\d{1,3}(?:,\d{3})+(?![\d])|\d+(?:\.\d+)?)"
                    r"(?:\s*[·×]\s*10([⁻⁰¹²³⁴⁵⁶⁷⁸⁹]+)|[eE]([-+]?\d+))?(?![\w.])")
PROGRESS_NUMBER = r"([-+]?\d+(?:\.\d+)?(?:e[-+]?\d+)?)"
# Progress-line quantities of the last cycle: (pattern, [summary.json key per group]).
PROGRESS_KEYS = [
    (r"Dorfler: \d+ -> (\d+) elements", ["elements"]),
    (r"(\d+) DOFs \(stress (\d+), displacement (\d+), rotation (\d+)\)",
     ["dofs.total", "dofs.stress", "dofs.displacement", "dofs.rotation"]),
    (r"estimate \| (\d+) DOFs, eta = " + PROGRESS_NUMBER, ["dofs.total", "eta.total"]),
    (r"eta / \|A\^1/2 sigma_h\| = " + PROGRESS_NUMBER, ["eta.relative"]),
    (r"force \(" + PROGRESS_NUMBER + r", " + PROGRESS_NUMBER + r"\)", [None, "contact.force[1]"]),
    (r"half-width " + PROGRESS_NUMBER, ["contact.half_width"]),
    (r"\(from the area " + PROGRESS_NUMBER + r"\)", ["contact.equivalent_half_width"]),
    (r"max pressure " + PROGRESS_NUMBER, ["contact.max_pressure"]),
    (r"stick " + PROGRESS_NUMBER + r" \((\d+) stick, (\d+) slip points\)",
     ["contact.stick_half_width", "contact.points.stick", "contact.points.slip"]),
    (r"(\d+) Newton steps", ["contact.newton_iterations"]),
    (r"reaction Top \(" + PROGRESS_NUMBER + r", " + PROGRESS_NUMBER + r"\)", [None, "reactions.Top.force[1]"]),
    (r"contact area " + PROGRESS_NUMBER + r" \(stick " + PROGRESS_NUMBER + r"\)",
     ["contact.area", "contact.stick_area"]),
    (r"cycle summary \| (\d+) DOFs, eta " + PROGRESS_NUMBER, ["dofs.total", "eta.total"]),
]


def key_pointer(key):
    """`contact.force[1]` -> /cycles/-1/contact/force/1 (the last cycle of summary.json)."""
    return "/cycles/-1/" + re.sub(r"\[(\d+)\]", r"/\1", key).replace(".", "/")


def number_value(text, exponent=None):
    """(value, tolerance: half a unit of the last digit written) of a quoted number."""
    digits = text.replace(",", "").replace("−", "-")
    scale = 10.0 ** int(exponent.translate(SUPERSCRIPT)) if exponent else 1.0
    return float(digits) * scale, precision_tolerance(digits, scale)


def printed_value(text):
    """(value, tolerance) of a number as the program prints it: 0.00377901, 4.96757e-07."""
    mantissa, _, exponent = text.lower().partition("e")
    scale = 10.0 ** int(exponent) if exponent else 1.0
    return float(mantissa) * scale, precision_tolerance(mantissa, scale)


def stored_main_values(root):
    """{pointer: value} of the eq:/near: checks of the main job's stored run (deck as shipped)."""
    values = {}
    for test, _line, checks in stored_runs(root).get("hertz2d.xml", []):
        if test != MAIN_TEST:
            continue
        for key, value in checks.items():
            kind, _, pointer = key.partition(":")
            if kind in ("eq", "near"):
                try:
                    values[pointer] = float(value.split(":")[0])
                except ValueError:
                    pass
    return values


def compare_quoted(path, line, key, value, tol, stored, findings, where):
    pointer = key_pointer(key)
    if pointer not in stored:
        findings.add(path, line, f"{where} quotes {key} = {value:.6g} for the main job, but {MAIN_TEST} "
                                 f"stores no value for {pointer} (tests/expected): no test "
                                 f"asserts it")
    elif abs(value - stored[pointer]) > tol * (1 + 1e-9) + 1e-300:
        findings.add(path, line, f"{where} quotes {key} = {value:.6g} for the main job, but {MAIN_TEST} "
                                 f"stores {stored[pointer]:.10g}")


def check_main_numbers(root, findings):
    path = os.path.join(root, "README.md")
    if not os.path.exists(path):
        return
    stored = stored_main_values(root)
    deck = os.path.join(root, "input", "hertz2d.xml")
    cycles = deck_cycles(deck) if os.path.exists(deck) else None
    text = open(path, encoding="utf-8").read()
    quoted = 0
    for offset, unit, in_code, heading in sentences(text):
        if "main job" not in heading.lower():
            continue
        line = line_of(text, offset)
        if in_code:
            m = PROGRESS.search(unit)
            if not m or int(m.group(1)) != int(m.group(2)) or (cycles is not None and int(m.group(1)) != cycles):
                continue
            for pattern, keys in PROGRESS_KEYS:
                for pm in re.finditer(pattern, unit):
                    for group, key in enumerate(keys, 1):
                        if key is None:
                            continue
                        value, tol = printed_value(pm.group(group))
                        compare_quoted(path, line, key, value, tol, stored, findings, "the progress line")
                        quoted += 1
            if "eta = " in unit and "(" in unit:
                parts = re.search(r"eta = [^ ]+ \((.*?)\)", unit)
                for name, number in re.findall(r"(\w+) " + PROGRESS_NUMBER, parts.group(1) if parts else ""):
                    value, tol = printed_value(number)
                    total = stored.get(key_pointer("eta.total"))
                    if total and value < 1e-10 * total:
                        continue  # a part at round-off (oscillation of zero data, tension)
                    compare_quoted(path, line, "eta." + name, value, tol, stored, findings, "the progress line")
                    quoted += 1
            continue
        if not unit.startswith("|"):
            continue
        cells = [c.strip() for c in unit.strip().strip("|").split("|")]
        if len(cells) < 3:
            continue
        keys = re.findall(r"`([A-Za-z_][\w.]*(?:\[\d+\])?)`", cells[1])
        if not keys:
            continue
        remark_free = re.sub(r"\([^()]*\)", "", cells[2])
        numbers = list(NUMBER.finditer(remark_free))
        if len(numbers) != len(keys):
            findings.add(path, line, f"the main job's table row '{cells[0]}' names {len(keys)} key(s) "
                                     f"but gives {len(numbers)} number(s) outside parentheses")
            continue
        for key, m in zip(keys, numbers):
            if m.group(3):
                value, tol = printed_value(m.group(1).replace(",", "") + "e" + m.group(3))
            else:
                value, tol = number_value(m.group(1), m.group(2))
            if m.group(0).startswith(("-", "−")):
                value = -value
            compare_quoted(path, line, key, value, tol, stored, findings, "the table")
            quoted += 1
    if quoted == 0:
        findings.add(path, 1, "no number of the main job found under a heading about the main job "
                              "(the table with summary.json keys, the progress lines of the last cycle)")


# --- issue numbers -------------------------------------------------------------------------------

def check_issue_numbers(root, findings):
    for top in ISSUE_SCOPE:
        start = os.path.join(root, top)
        paths = [start] if os.path.isfile(start) else []
        for dirpath, dirnames, filenames in os.walk(start):
            dirnames[:] = sorted(d for d in dirnames if d not in ("__pycache__", ".git"))
            paths += [os.path.join(dirpath, f) for f in sorted(filenames)]
        for path in paths:
            suffix = os.path.splitext(path)[1]
            if suffix not in TEXT_SUFFIXES and os.path.basename(path) != "CMakeLists.txt":
                continue
            try:
                text = open(path, encoding="utf-8").read()
            except (UnicodeDecodeError, OSError):
                continue
            for m in ISSUE.finditer(text):
                findings.add(path, line_of(text, m.start()), f'cites an issue number: "{m.group(0)}"')


CHECKS = {"decks": check_decks, "main-job": check_main_job, "main-numbers": check_main_numbers,
          "issue-numbers": check_issue_numbers}


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--root", required=True, help="the repository (or fixture) to check")
    parser.add_argument("--check", default="decks,main-job,main-numbers",
                        help="comma-separated: " + ", ".join(CHECKS) +
                             " (default: decks,main-job,main-numbers)")
    parser.add_argument("--show", type=int, default=10, help="findings to print (default 10)")
    args = parser.parse_args()
    root = os.path.abspath(args.root)
    names = [c for c in args.check.split(",") if c]
    unknown = [c for c in names if c not in CHECKS]
    if unknown:
        parser.error("unknown check(s): " + ", ".join(unknown))
    findings = Findings(root)
    for name in names:
        CHECKS[name](root, findings)
    for item in findings.items[:args.show]:
        print(item)
    if len(findings.items) > args.show:
        print(f"... and {len(findings.items) - args.show} more")
    label = ",".join(names)
    if findings.items:
        print(f"check_docs ({label}): {len(findings.items)} finding(s) in {root}")
        return 1
    print(f"check_docs ({label}): no findings in {root}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
