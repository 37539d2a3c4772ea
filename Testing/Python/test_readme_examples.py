"""Every code block of README.md runs, or says why it is not run.

Extracts the fenced blocks of README.md (at the repository's top):
- ```python blocks are run, each in a fresh /usr/bin/python3 (this test's
  interpreter, same PYTHONPATH) in an empty temporary folder, with the
  bundled data path "Testing/Data/" replaced by --data. A block whose first
  line is the comment CONTINUES continues the example of "Using it": it runs
  after that block, in the same process. Rendering uses the test's display
  (Xvfb, or Mesa EGL in the headless pass: offscreen_window chooses).
- ```json blocks are parsed; the batch example must equal the file it quotes
  (Utilities/examples/bracket_spec.json), "_" comment keys aside.
- every other block (sh, cpp, plain) must be preceded by an HTML comment
  <!-- readme-test: skip: <reason> --> giving why it is not run here; a block
  without one fails this test, so new blocks cannot silently rot.
"""
import argparse
import json
import os
import re
import subprocess
import sys

FAILURES = []
HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
CONTINUES = '# Continues the example of "Using it"'
SKIP = re.compile(r"<!--\s*readme-test:\s*skip:\s*(.*?)\s*-->")
FENCE = re.compile(r"^```(\w*)[ \t]*\n(.*?)^```[ \t]*$", re.M | re.S)


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        FAILURES.append(what)


def blocks(text):
    """(language, code, line number, skip reason or None) of every fenced block."""
    out = []
    for m in FENCE.finditer(text):
        line = text.count("\n", 0, m.start()) + 1
        before = text[:m.start()].rstrip().splitlines()
        reason = None
        if before:
            s = SKIP.search(before[-1])
            reason = s.group(1) if s else None
        out.append((m.group(1), m.group(2), line, reason))
    return out


def run_python(code, data, cwd, label):
    code = code.replace("Testing/Data/", data.rstrip("/") + "/")
    path = os.path.join(cwd, "block.py")
    with open(path, "w") as f:
        f.write(code)
    try:
        r = subprocess.run([sys.executable, path], cwd=cwd, capture_output=True, text=True,
                           timeout=600)
    except subprocess.TimeoutExpired:
        check(False, "%s: timed out" % label)
        return
    if r.stdout.strip():
        print("    stdout: " + r.stdout.strip().replace("\n", "\n            "))
    ok = r.returncode == 0
    if not ok:
        print("    stderr: " + r.stderr.strip()[-3000:].replace("\n", "\n            "))
    check(ok, "%s runs (exit %d)" % (label, r.returncode))


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--data", required=True)
    parser.add_argument("--temp", required=True)
    args = parser.parse_args()
    data = os.path.abspath(args.data)
    with open(os.path.join(ROOT, "README.md"), encoding="utf-8") as f:
        text = f.read()
    found = blocks(text)
    check(len(found) > 10, "README.md has %d code blocks" % len(found))
    base = [code for lang, code, _, _ in found
            if lang == "python" and "volume_property = vtkVolumeProperty()" in code]
    check(len(base) == 1, "exactly one 'Using it' example defines volume_property")
    ran = skipped = 0
    for index, (lang, code, line, reason) in enumerate(found):
        label = "README.md:%d (```%s)" % (line, lang or "")
        if reason is not None:
            print("skip %s: %s" % (label, reason))
            skipped += 1
            continue
        if lang == "python":
            cwd = os.path.join(os.path.abspath(args.temp), "readme_block_%02d" % index)
            os.makedirs(cwd, exist_ok=True)
            if code.startswith(CONTINUES):
                if not base:
                    check(False, label + ": no 'Using it' example to continue")
                    continue
                code = base[0] + "\n# --- continued ---\n" + code
            run_python(code, data, cwd, label)
            ran += 1
        elif lang == "json":
            try:
                spec = json.loads(code)
            except ValueError as e:
                check(False, "%s parses as JSON: %s" % (label, e))
                continue
            with open(os.path.join(ROOT, "Utilities", "examples", "bracket_spec.json")) as f:
                quoted = json.load(f)
            def strip(d):  # "_" keys are comments
                return {k: v for k, v in d.items() if not k.startswith("_")}
            check(strip(spec) == strip(quoted),
                  label + " equals Utilities/examples/bracket_spec.json (comments aside)")
            ran += 1
        else:
            check(False, label + ": neither run nor marked <!-- readme-test: skip: reason -->")
    print("%d blocks checked, %d skipped with a reason" % (ran, skipped))
    if FAILURES:
        print("%d failure(s)" % len(FAILURES))
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
