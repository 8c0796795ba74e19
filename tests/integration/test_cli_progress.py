"""The CLI's progress and version (issue 19 item 5): `hexlayer --version` gives package.xml's version; with stderr
a pipe, plain lines (one per finished stage, no control characters), the same stages as the report's timings;
with --machine, "@running <stage>" before each "@progress <stage>: <s> s"; with stderr a terminal (a pseudo
terminal), one status line redrawn in place ("\\r\\033[K"), the finished stages' lines kept. The quad stage's
budgets (--quad-try-budget, --quad-budget): a try out of its budget is a failed try.

Run by CTest as: /usr/bin/python3 test_cli_progress.py --hexlayer PATH --source DIR
"""
import json
import os
import pty
import re
import subprocess
import tempfile
import unittest

import harness

CLEAR = "\r\033[K"


def sample(name):
    return os.path.join(harness.args.source, "Resources", "samples", name)


class Version(unittest.TestCase):
    def test_version_is_package_xml_s(self):
        with open(os.path.join(harness.args.source, "package.xml")) as f:
            version = re.search(r"<version>([^<]+)</version>", f.read()).group(1)
        done = subprocess.run([harness.args.hexlayer, "--version"], capture_output=True, text=True, timeout=60)
        self.assertEqual(done.returncode, 0, done.stderr)
        self.assertEqual(done.stdout.strip(), "hexlayer " + version)


class Progress(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def command(self, name, *extra):
        out = os.path.join(self.tmp.name, name + ".inp")
        report = os.path.join(self.tmp.name, name + ".json")
        return [harness.args.hexlayer, "mesh", sample("plate_holes.step"), "-o", out, "--report", report, *extra], report

    def stages(self, report):
        with open(report) as f:
            return json.load(f)["timings_s"]

    def test_plain_lines_when_stderr_is_a_pipe(self):
        command, report = self.command("plain")
        done = subprocess.run(command, capture_output=True, text=True, timeout=600)
        self.assertEqual(done.returncode, 0, done.stderr[-2000:])
        self.assertNotIn("\r", done.stderr)
        self.assertNotIn("\033", done.stderr)
        finished = re.findall(r"^hexlayer: (\w+): [0-9.]+ s$", done.stderr, re.M)
        self.assertCountEqual(finished, self.stages(report))
        for line in done.stderr.splitlines():
            self.assertRegex(line, r"^hexlayer: (\w+: [0-9.]+ s|quad_mesh: \d+/\d+|warning: .*)$")

    def test_machine_lines_announce_each_stage(self):
        command, report = self.command("machine", "--machine")
        done = subprocess.run(command, capture_output=True, text=True, timeout=600)
        self.assertEqual(done.returncode, 0, done.stderr[-2000:])
        running = None
        finished = []
        for line in done.stderr.splitlines():
            start = re.fullmatch(r"@running (\w+)", line)
            step = re.fullmatch(r"@running (\w+) (\d+) (\d+)", line)
            end = re.fullmatch(r"@progress (\w+): [0-9.]+ s", line)
            if start:
                running = start.group(1)
            elif step:
                self.assertEqual(step.group(1), running)
                self.assertLessEqual(int(step.group(2)), int(step.group(3)))
            elif end:
                self.assertEqual(end.group(1), running, "finished the stage that was announced")
                finished.append(running)
        self.assertCountEqual(finished, self.stages(report))

    def test_status_line_on_a_terminal(self):
        command, report = self.command("terminal")
        controller, terminal = pty.openpty()
        child = subprocess.Popen(command, stdout=subprocess.DEVNULL, stderr=terminal, env=dict(os.environ, TERM="xterm"))
        os.close(terminal)
        chunks = []
        while True:
            try:
                data = os.read(controller, 65536)
            except OSError:  # the child closed the terminal
                break
            if not data:
                break
            chunks.append(data)
        os.close(controller)
        self.assertEqual(child.wait(timeout=600), 0)
        text = b"".join(chunks).decode()
        self.assertIn(CLEAR + "hexlayer: geometry  ", text, "a stage's status line, drawn in place")
        kept = re.findall(r"hexlayer: (\w+): [0-9.]+ s\r?\n", text)
        self.assertCountEqual(kept, self.stages(report))
        self.assertEqual(text[text.rindex("\n") + 1:].replace(CLEAR, ""), "", "no status line left at the end")


class QuadBudget(unittest.TestCase):
    """box_close_holes's quads come from Gmsh (an open box bent sharp with two holes in its floor too close for their
    pockets: no patch grid, and the single grids cut its bends): with a millisecond per Gmsh try every try runs out of
    it and fails, and the part is refused (exit 4) saying so; with a spent stage budget no try starts. (The real
    U-channel was the part here until its quads became the patch grid, which needs no Gmsh try.)"""

    def run_with(self, *options):
        part = os.path.join(harness.args.source, "Resources", "samples", "box_close_holes.step")
        with tempfile.TemporaryDirectory() as tmp:
            return subprocess.run([harness.args.hexlayer, "mesh", part, "-o", os.path.join(tmp, "m.inp"), "--quiet",
                                   *options], capture_output=True, text=True, timeout=600)

    def test_tries_out_of_their_budget_fail(self):
        done = self.run_with("--quad-try-budget", "0.001")
        self.assertEqual(done.returncode, 4, done.stderr)
        # Its chordal surface and its faired levels: 12 tries each, and HexLayer's own patches (no quads yet).
        self.assertIn("timed out after 0.001 s (38 Gmsh tries, 38 failed, 38 out of their time budget)", done.stderr)

    def test_no_try_after_the_stage_budget(self):
        done = self.run_with("--quad-budget", "0.001")
        self.assertEqual(done.returncode, 4, done.stderr)
        self.assertIn("(0 Gmsh tries, 0 failed, 0 out of their time budget, 12 not started: the stage's budget of "
                      "0.001 s was spent)", done.stderr)


if __name__ == "__main__":
    harness.main()
