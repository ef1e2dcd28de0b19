#!/usr/bin/env python3
"""The setup sheet (clpost sheet) read back with an HTML parser and checked against what
`clpost check` and `clpost plan --format json` print for the same file on the same machine: each
tool, the cycle time, each thread's passes; the holes against the CL by hand; escaping of what the
CL says; the JSON form; and a batch writing sheets beside its programs, its report linking them.

Usage: sheet_test.py CLPOST SOURCE_DIR"""
import json
import os
import re
import subprocess
import sys
import tempfile
import unittest
from html.parser import HTMLParser

CLPOST = ""
SRC = ""
MACHINE = "fanuc-0i-t"
DATE = "2026-01-02 03:04 UTC"


def run(*args, ok=True, env=None):
    p = subprocess.run([CLPOST, *args], capture_output=True, text=True, env=env)
    if ok and p.returncode != 0:
        raise AssertionError(f"clpost {' '.join(args)}: exit {p.returncode}\n{p.stderr}")
    return p


class Sheet(HTMLParser):
    """The page as data: tables by id or class (rows of cell texts, header row apart), facts
    tables as dicts, per section; the element names met; the text of #cycle-time."""

    def __init__(self):
        super().__init__(convert_charrefs=True)
        self.tags = []          # every start tag, in order
        self.section = None     # id of the section being read
        self.tables = []        # {"section", "id", "cls", "head", "rows"}
        self.table = None
        self.cell = None
        self.row = None
        self.in_head = False
        self.capture = None     # (key, text) being captured
        self.texts = {}
        self.open = []          # element stack (void elements left out)

    VOID = {"meta", "br", "img", "hr", "input", "link"}

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        self.tags.append(tag)
        if tag not in self.VOID:
            self.open.append(tag)
        if tag == "section":
            self.section = a.get("id")
        elif tag == "table":
            self.table = {"section": self.section, "id": a.get("id"), "cls": a.get("class"),
                          "head": [], "rows": []}
            self.tables.append(self.table)
        elif tag == "thead":
            self.in_head = True
        elif tag == "tr":
            self.row = []
        elif tag in ("td", "th") and self.row is not None:
            self.cell = ""
        if a.get("id") in ("cycle-time",) or tag in ("h1", "title"):
            self.capture = (a.get("id") or tag, "")

    def handle_endtag(self, tag):
        if tag in self.VOID:
            return
        assert self.open and self.open[-1] == tag, f"</{tag}> closes <{self.open[-1:]}>"
        self.open.pop()
        if tag in ("td", "th") and self.cell is not None:
            self.row.append(self.cell.strip())
            self.cell = None
        elif tag == "tr" and self.row is not None:
            (self.table["head"] if self.in_head else self.table["rows"]).append(self.row)
            self.row = None
        elif tag == "thead":
            self.in_head = False
        elif tag == "table":
            self.table = None
        elif tag == "section":
            self.section = None
        if self.capture and tag in ("strong", "h1", "title"):
            self.texts[self.capture[0]] = self.capture[1]
            self.capture = None

    def handle_data(self, data):
        if self.cell is not None:
            self.cell += data
        if self.capture:
            self.capture = (self.capture[0], self.capture[1] + data)

    def find(self, section=None, cls=None, id=None):
        return [t for t in self.tables
                if (section is None or t["section"] == section)
                and (cls is None or t["cls"] == cls) and (id is None or t["id"] == id)]

    def facts(self, section=None, id=None):
        (t,) = self.find(section=section, cls="facts", id=id)
        return {r[0]: r[1] for r in t["rows"]}


def read(path):
    with open(path, encoding="utf-8") as f:
        return f.read()


def parse(text):
    s = Sheet()
    s.feed(text)
    s.close()
    assert not s.open, f"elements left open: {s.open}"
    return s


def records(table):
    return [dict(zip(table["head"][0], r)) for r in table["rows"]]


CHECK_TOOL = re.compile(
    r"^  T(\d+) offset (-?\d+): ([0-9:.]+)(?:, (X\S+ to X\S+, Z\S+ to Z\S+) (?:mm|in))?"
    r"(?:, nose radius ([^,]+))?(?:, (.*))?$")
CHECK_TOTAL = re.compile(r"^  cycle time ([0-9:.]+), (\d+) tool changes?")


def check_lines(cl):
    """`clpost check`'s tool lines and total for `cl`."""
    err = run("check", "-m", MACHINE, cl).stderr
    tools, total = [], None
    for line in err.splitlines():
        m = CHECK_TOOL.match(line)
        if m:
            tools.append(m.groups())
        m = CHECK_TOTAL.match(line)
        if m:
            total = m.groups()
    return tools, total


class PartTurned(unittest.TestCase):
    """samples/part-turned.apt: six tools, three holes, one M24x2 thread."""

    @classmethod
    def setUpClass(cls):
        cls.cl = os.path.join(SRC, "samples", "part-turned.apt")
        cls.html = run("sheet", "-m", MACHINE, "--date", DATE, cls.cl).stdout
        cls.page = parse(cls.html)
        cls.plan = json.loads(run("plan", "-m", MACHINE, "--format", "json", cls.cl).stdout)
        cls.check_tools, cls.check_total = check_lines(cls.cl)

    def test_self_contained(self):
        # No script, no external file, stylesheet, image or font: the page opens from a stick.
        self.assertNotIn("script", self.page.tags)
        self.assertNotIn("link", self.page.tags)
        self.assertNotIn("img", self.page.tags)
        self.assertIsNone(re.search(r"(src|href)\s*=|url\((?!#)|@import|@font-face", self.html))
        self.assertTrue(self.html.startswith("<!DOCTYPE html>"))

    def test_program_facts(self):
        f = self.page.facts(id="program")
        self.assertEqual(f["Part"], "PART-TURNED")
        self.assertEqual(f["Date"], DATE)
        self.assertTrue(f["Machine"].startswith(MACHINE))
        self.assertEqual(f["Threads"], "1")
        self.assertEqual(f["Holes"], "3")

    def test_tools_match_check(self):
        (t,) = self.page.find(section="tools", cls="tools")
        rows = records(t)
        self.assertEqual(len(self.check_tools), 6)
        self.assertEqual(len(rows), len(self.check_tools))
        for n, (row, (tool, offset, time, reach, nose, text)) in enumerate(
                zip(rows, self.check_tools), 1):
            self.assertEqual(row["#"], str(n))
            self.assertEqual(row["Tool"], "T" + tool)
            self.assertEqual(row["Offset"], offset)
            self.assertEqual(row["Total"], time)
            self.assertEqual(row["Reach"], reach or "")
            self.assertEqual(row["Nose radius"], nose or "-")
            self.assertEqual(row["Description"], text or "")
        # The tools in the order the CL loads them, T1 .. T6.
        self.assertEqual([r["Tool"] for r in rows], [f"T{i}" for i in range(1, 7)])

    def test_feeds_speeds_and_lines(self):
        (t,) = self.page.find(section="tools", cls="tools")
        rows = {r["Tool"]: r for r in records(t)}
        # From the CL: T1 FEDRAT/0.2,MMPR at 800 rpm; T4 taps M10x1.5 at 300 rpm (the CL's 450
        # mm/min is the pitch per revolution);
        # T5 the M24x2 thread at 600 rpm (its feed is the lead per revolution).
        self.assertEqual(rows["T1"]["Feeds"], "0.2 mm/rev")
        self.assertEqual(rows["T1"]["Speeds"], "800 rpm")
        self.assertEqual(rows["T4"]["Feeds"], "1.5 mm/rev")  # the lead: 1.5 x 300 = 450 mm/min
        self.assertEqual(rows["T4"]["Speeds"], "300 rpm")
        self.assertEqual(rows["T5"]["Feeds"], "2 mm/rev")
        self.assertEqual(rows["T5"]["Speeds"], "600 rpm")
        self.assertEqual(rows["T6"]["Feeds"], "0.05 mm/rev")
        # NC lines: consecutive ranges, each tool's starting after the last one's.
        last = 0
        for r in records(t):
            first, end = map(int, r["NC lines"].split("-"))
            self.assertGreater(first, last)
            self.assertGreaterEqual(end, first)
            last = end

    def test_nc_lines_are_the_programs(self):
        # Each tool's first NC line is its tool change, with the machine's program_header (whose
        # lines come before the tools': the program, its 6 tools and the cycle time, 8 lines
        # here) and without one.
        for sets in ([], ["--set", "templates.program_header=[]"]):
            nc = run("-m", MACHINE, *sets, self.cl).stdout.splitlines()
            page = parse(run("sheet", "-m", MACHINE, *sets, "--date", DATE, self.cl).stdout)
            (t,) = page.find(section="tools", cls="tools")
            rows = records(t)
            for r in rows:
                first, last = map(int, r["NC lines"].split("-"))
                self.assertRegex(nc[first - 1], r"^N\d+ T0*" + r["Tool"][1:] + "0")
            # The last tool ends before the program end (M30 and what follows it).
            self.assertEqual(nc[last], nc[-2])
            self.assertRegex(nc[last], "M30")
            self.assertEqual(int(rows[0]["NC lines"].split("-")[0]), 5 if sets else 5 + 8)

    def test_cutting_times_by_hand(self):
        (t,) = self.page.find(section="tools", cls="tools")
        rows = {r["Tool"]: r for r in records(t)}
        # T1 feeds 16 + 44 + 4 = 64 mm at 0.2 mm/rev x 800 rpm = 160 mm/min: 24 s.
        self.assertEqual(rows["T1"]["Cutting"], "0:24.0")
        # T6 parts off from X16 to X-0.5 (radius): 16.5 mm at 0.05 x 700 = 35 mm/min: 28.29 s.
        self.assertEqual(rows["T6"]["Cutting"], "0:28.3")

    def test_cycle_time_matches_check(self):
        self.assertEqual(self.page.texts["cycle-time"], self.check_total[0])
        self.assertEqual(self.page.facts(id="program")["Cycle time"], self.check_total[0])
        self.assertEqual(self.page.facts(id="program")["Tools"], self.check_total[1])

    def test_threads_match_plan(self):
        threads = self.plan["threads"]
        self.assertEqual(len(threads), 1)
        for k, th in enumerate(threads, 1):
            sec = f"thread-{k}"
            facts = self.page.facts(section=sec)
            self.assertEqual(facts["Pitch"], f"{th['pitch']:g} mm")
            self.assertEqual(facts["Lead"], f"{th['lead']:g} mm")
            self.assertEqual(facts["Starts"], str(th["starts"]))
            self.assertEqual(float(facts["Depth"].split()[0]), th["depth"])
            self.assertEqual(float(facts["Run-in"].split()[0]), th["run_in"])
            self.assertEqual(float(facts["Run-out"].split()[0]), th["run_out"])
            self.assertEqual(facts["Spindle speed"], f"{th['rpm']:g} rpm")
            self.assertIn("Output", facts)
            (t,) = self.page.find(section=sec, cls="passes")
            rows = records(t)
            self.assertEqual(len(rows), len(th["passes"]))
            for row, p in zip(rows, th["passes"]):
                self.assertEqual(int(row["Pass"]), p["n"])
                self.assertEqual(int(row["Start"]), p["start"])
                self.assertEqual(float(row["Depth"]), p["depth"])
                self.assertEqual(float(row["Shift"]), p["shift"])
                self.assertEqual(row["Kind"], p["kind"])
            # THREAD/ON,DEPTH,1.227,CUTS,5,FINCUT,1,0.05: 5 roughing passes, one finish of 0.05,
            # the last pass at the full depth.
            kinds = [p["kind"] for p in th["passes"]]
            self.assertEqual(kinds.count("finish"), 1)
            self.assertEqual(float(rows[-1]["Depth"]), 1.227)
            self.assertAlmostEqual(float(rows[-1]["Step"]), 0.05, places=9)
        self.assertEqual(self.page.tags.count("svg"), 2)  # the section and the backplot

    def test_holes_as_the_cl_says(self):
        (t,) = self.page.find(section="holes", cls="holes")
        rows = records(t)
        # CYCLE/DRILL DEPTH 3, CYCLE/DEEP DEPTH 22 STEP 5, CYCLE/TAP DEPTH 16, each at Z0.
        self.assertEqual([r["Cycle"] for r in rows], ["drilling", "peck drilling", "tapping"])
        self.assertEqual([r["Depth"] for r in rows], ["3", "22", "16"])
        self.assertEqual([r["Position"] for r in rows], ["X0 Z0"] * 3)
        self.assertEqual(rows[1]["Pecks"], "5")
        self.assertEqual(rows[0]["Dwell"], "0.5 s")
        # What the program writes, as its reader calls it: fanuc-0i-t's hole_dwell, hole_peck
        # and hole_tap_rigid templates (posts/fanuc-lathe.yaml: G83 P, G83 Q, M29 G84).
        self.assertEqual([r["Output"] for r in rows],
                         ["drilling with a dwell (G83)", "peck drilling (G83)",
                          "rigid tapping (G84)"])
        # The sample gives no CUTTER/ or TLDATA/.
        self.assertEqual([r["Tool diameter"] for r in rows], ["-"] * 3)

    def test_json_is_the_same_data(self):
        j = json.loads(run("sheet", "-m", MACHINE, "--date", DATE, "--format", "json",
                           self.cl).stdout)
        self.assertEqual(j["cycle_time"], self.check_total[0])
        self.assertEqual([t["time"] for t in j["tools"]], [t[2] for t in self.check_tools])
        self.assertEqual(j["plan"], self.plan)
        self.assertEqual(len(j["holes"]), 3)
        self.assertEqual([h["tool_diameter"] for h in j["holes"]], [None] * 3)
        self.assertEqual(j["date"], DATE)

    def test_source_date_epoch(self):
        env = dict(os.environ, SOURCE_DATE_EPOCH="86400")
        page = parse(run("sheet", "-m", MACHINE, self.cl, env=env).stdout)
        self.assertEqual(page.facts(id="program")["Date"], "1970-01-02 00:00 UTC")
        env["SOURCE_DATE_EPOCH"] = "soon"
        p = run("sheet", "-m", MACHINE, self.cl, env=env, ok=False)
        self.assertEqual(p.returncode, 2)
        self.assertIn("SOURCE_DATE_EPOCH 'soon' is not a whole number of seconds", p.stderr)


class Fallback(unittest.TestCase):
    def test_fallback_as_the_program_says(self):
        # A chained thread on fanuc-0i-t: neither G76 nor G92 cuts it; the program's comment
        # names the first that was not used and what was written instead.
        cl = os.path.join(SRC, "samples", "threads", "chain.apt")
        nc = run("-m", MACHINE, cl).stdout
        facts = parse(run("sheet", "-m", MACHINE, "--date", DATE, cl).stdout).facts(
            section="thread-1")
        self.assertEqual(facts["Output"], "emulation")
        self.assertEqual(facts["Fallback"],
                         "G76 not used: a chained thread: G76 cuts one straight thread line; "
                         "G92 not used: a chained thread: G92 cuts one straight line per pass")
        first = facts["Fallback"].split("; ")[0]
        self.assertIn(f"({first}. {facts['Output']} instead)".upper(), nc)


HOSTILE = """PARTNO <b>P&Q</b>
UNITS/MM
PPRINT TOOL: <script>alert(1)</script> & "x" 'y'
LOADTL/1,ADJUST,1
SPINDL/800,RPM,CLW
FEDRAT/0.2,MMPR
PPRINT <script>&
RAPID
GOTO/16,0,2
GOTO/12,0,-10
FOO/1
FINI
"""


class Escaping(unittest.TestCase):
    def test_cl_text_is_escaped(self):
        with tempfile.TemporaryDirectory() as d:
            cl = os.path.join(d, "hostile.apt")
            with open(cl, "w") as f:
                f.write(HOSTILE)
            html = run("sheet", "-m", MACHINE, "--date", DATE, cl).stdout
        page = parse(html)
        self.assertNotIn("script", page.tags)
        self.assertNotIn("b", page.tags)
        self.assertNotIn("<script>", html)
        self.assertIn("&lt;script&gt;alert(1)&lt;/script&gt; &amp; &quot;x&quot; &apos;y&apos;",
                      html)
        self.assertEqual(page.texts["h1"], "Setup sheet: <b>P&Q</b>")
        (t,) = page.find(section="tools", cls="tools")
        self.assertEqual(records(t)[0]["Description"], "<script>alert(1)</script> & \"x\" 'y'")
        (w,) = page.find(section="warnings", cls="warnings")
        rows = records(w)
        self.assertIn("11", [r["CL line"] for r in rows])


class Batch(unittest.TestCase):
    def test_batch_writes_sheets_and_links_them(self):
        with tempfile.TemporaryDirectory() as d:
            bad = os.path.join(d, "bad.apt")
            with open(bad, "w") as f:
                f.write("GOTO/1,2,\nFINI\n")
            out = os.path.join(d, "out")
            report = os.path.join(d, "report.json")
            inputs = [os.path.join(SRC, "samples", n) for n in ("part-turned.apt", "thread-m20.apt")]
            p = run("-m", MACHINE, "-d", out, "--sheets", "--keep-going", "--report", report,
                    "--date", DATE, *inputs, bad, ok=False)
            self.assertEqual(p.returncode, 1, p.stderr)
            files = json.loads(read(report))["files"]
            self.assertEqual([f["status"] for f in files][2], "error")
            self.assertIsNone(files[2]["sheet"])
            self.assertFalse(os.path.exists(os.path.join(out, "bad.html")))
            for f, stem in zip(files[:2], ("part-turned", "thread-m20")):
                self.assertEqual(f["sheet"], os.path.join(out, stem + ".html"))
                self.assertEqual(f["output"], os.path.join(out, stem + ".nc"))
                page = parse(read(f["sheet"]))
                facts = page.facts(id="program")
                self.assertEqual(facts["NC program"], f["output"])
                self.assertEqual(facts["Date"], DATE)
            # The sheet of a batch is the sheet `clpost sheet` writes, but for the NC file's name.
            alone = run("sheet", "-m", MACHINE, "--date", DATE, "--nc", files[0]["output"],
                        inputs[0]).stdout
            self.assertEqual(read(files[0]["sheet"]), alone)

    def test_sheet_on_a_post(self):
        with tempfile.TemporaryDirectory() as d:
            cl = os.path.join(SRC, "samples", "part-turned.apt")
            nc = os.path.join(d, "part.nc")
            run("-m", MACHINE, "-o", nc, "--sheet", os.path.join(d, "sheets"), "--date", DATE, cl)
            sheet = os.path.join(d, "sheets", "part-turned.html")
            self.assertEqual(read(sheet),
                             run("sheet", "-m", MACHINE, "--date", DATE, "--nc", nc, cl).stdout)
            # A sheet that cannot be written: no program either (exit 1, as for a batch's file).
            os.remove(nc)
            blocker = os.path.join(d, "file")
            with open(blocker, "w") as f:
                f.write("not a directory\n")
            p = run("-m", MACHINE, "-o", nc, "--sheet", blocker, cl, ok=False)
            self.assertEqual(p.returncode, 1, p.stderr)
            self.assertIn(f"clpost: error: cannot create the output directory '{blocker}'", p.stderr)
            self.assertFalse(os.path.exists(nc))
            self.assertEqual(sorted(os.listdir(d)), ["file", "sheets"])  # no temporary left


if __name__ == "__main__":
    CLPOST, SRC = sys.argv[1], sys.argv[2]
    unittest.main(argv=[sys.argv[0]] + sys.argv[3:], verbosity=2)
