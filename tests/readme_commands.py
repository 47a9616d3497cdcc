#!/usr/bin/env python3
"""Runs every command the README (and the docs pages with commands) shows, as a reader would.

Issue 31: the README had drifted (a script that failed, a file that did not exist). Each page's
```sh / ```bash blocks are read line by line (a trailing backslash joins the next line; blank and
comment-only lines are skipped) and run in order with bash, in one scratch folder the pages share
in turn (README first: the docs go on from its files), holding copies of the shipped examples/,
scripts/ and python/ and a link `build` to the build tree, with build/app on PATH. A ```python
block runs as one script against build/python, with the Python running this. A command that exits
non-zero fails the test, named with its page, line and stderr; so does a relative link to a file
or heading that is not there. Commands that
cannot run here are listed in EXCLUDED, each with why; an entry that no longer matches a command
fails too, so the list cannot outlive the text.

usage: readme_commands.py --source SRC --build BUILD [--no-python] [--keep-on-failure] [PAGE ...]
"""
import argparse
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

# Command prefix -> why it is not run here.
EXCLUDED = {
    "bash scripts/main.sh": "installs packages and runs the whole main job (minutes); CI runs it",
    "bash scripts/test.sh": "the test command itself, which runs this test",
    "/usr/bin/python3 -m venv": "the virtual-environment install builds the module from scratch "
    "(minutes); scripts/test-python-install.sh runs these lines in CI",
    ".venv/bin/": "needs the virtual environment above",
    "curvefold design": "opens a window and waits for the user; test_desktop_window drives it",
    "curvefold xr cylinder": "needs a headset (a real OpenXR runtime)",
}
# Exact commands (comments stripped) -> why.
EXCLUDED_EXACT = {
    "curvefold": "opens a window (or a headset session) and waits for the user",
}
PAGES = ["README.md", "docs/cli.md", "docs/formats.md", "docs/vr.md", "docs/development.md"]
# Pages whose links are checked but whose commands are not run (benchmarks take minutes).
LINKS_ONLY = ["docs/design.md", "docs/performance.md"]
TIMEOUT_S = 120


def blocks(text):
    """(language, first line number, lines) of every fenced block."""
    out, lang, start, body = [], None, 0, []
    for number, line in enumerate(text.split("\n"), 1):
        fence = re.match(r"^```\s*(\S*)\s*$", line)
        if fence and lang is None:
            lang, start, body = fence.group(1), number + 1, []
        elif fence and line.strip() == "```":
            out.append((lang, start, body))
            lang = None
        elif lang is not None:
            body.append(line)
    return out


def commands(lines, start):
    """(line number, command) for each shell command, continuations joined."""
    out, pending, first = [], "", None
    for offset, line in enumerate(lines):
        if not pending and (not line.strip() or line.lstrip().startswith("#")):
            continue
        if first is None:
            first = start + offset
        if line.endswith("\\"):
            pending += line[:-1] + " "
            continue
        out.append((first, pending + line))
        pending, first = "", None
    return out


def bare(command):
    """The command without its trailing comment or extra spaces (for the exclusion lists)."""
    return re.sub(r"\s+#.*$", "", " ".join(command.split()))


def excluded(command):
    text = bare(command)
    if text in EXCLUDED_EXACT:
        return text, EXCLUDED_EXACT[text]
    for prefix, why in EXCLUDED.items():
        if text.startswith(prefix):
            return prefix, why
    return None, None


def slug(heading):
    """GitHub's anchor for a heading."""
    return re.sub(r"[^\w\- ]", "", heading.strip().lower()).replace(" ", "-")


def broken_links(source, page, text):
    """Relative links (and their #anchors) that name no file or heading: a moved section."""
    out = []
    for target in re.findall(r"\]\(([^)\s]+)\)", text):
        if re.match(r"^[a-z]+:", target):
            continue
        path, _, anchor = target.partition("#")
        file = os.path.normpath(os.path.join(source, os.path.dirname(page), path)) if path else \
            os.path.join(source, page)
        if not os.path.exists(file):
            out.append(f"{page}: link {target}: no such file")
        elif anchor and file.endswith(".md"):
            with open(file, encoding="utf-8") as f:
                headings = {slug(h) for h in re.findall(r"^#+ (.*)$", f.read(), re.M)}
            if anchor not in headings:
                out.append(f"{page}: link {target}: no such heading")
    return out


def scratch(source, build):
    folder = tempfile.mkdtemp(prefix="readme-commands-")
    for shipped in ("examples", "scripts", "python"):
        if os.path.isdir(os.path.join(source, shipped)):
            shutil.copytree(os.path.join(source, shipped), os.path.join(folder, shipped))
    os.symlink(build, os.path.join(folder, "build"))
    return folder


def environment(args, folder):
    env = dict(os.environ)
    env["PATH"] = os.path.join(args.build, "app") + os.pathsep + env.get("PATH", "")
    env["PYTHONPATH"] = os.path.join(args.build, "python")
    # What a reader's run keeps (the fold cache, recent designs) stays in the scratch folder.
    env["HOME"] = folder
    env["XDG_STATE_HOME"] = os.path.join(folder, ".state")
    env["CURVEFOLD_CACHE_DIR"] = os.path.join(folder, ".cache")
    env.pop("DISPLAY", None)
    return env


def run_page(page, args, folder, env, used):
    with open(os.path.join(args.source, page), encoding="utf-8") as f:
        text = f.read()
    failures, ran = broken_links(args.source, page, text), 0
    for lang, start, body in blocks(text):
        if lang in ("sh", "bash"):
            runs = []
            for number, command in commands(body, start):
                key, why = excluded(command)
                if key:
                    used.add(key)
                    print(f"{page}:{number}: skipped ({why}): {bare(command)}")
                    continue
                if args.no_python and "build/python" in command:
                    print(f"{page}:{number}: skipped (no Python module in this build): {bare(command)}")
                    continue
                runs.append((number, ["bash", "-o", "pipefail", "-c", command], command))
        elif lang == "python" and not args.no_python:
            runs = [(start, [sys.executable, "-c", "\n".join(body)], f"the python block")]
        else:
            continue
        for number, argv, shown in runs:
            began = time.monotonic()
            try:
                result = subprocess.run(argv, cwd=folder, env=env, capture_output=True, text=True,
                                        timeout=TIMEOUT_S)
                code, err = result.returncode, result.stderr
            except subprocess.TimeoutExpired as e:
                code, err = "timeout", f"ran past {TIMEOUT_S} s; {e.stderr or ''}"
            ran += 1
            print(f"{page}:{number}: exit {code}, {time.monotonic() - began:.1f} s: {bare(shown)}")
            if code != 0:
                failures.append(f"{page}:{number}: `{shown}` exited {code}:\n{err.strip()[-2000:]}")
    return ran, failures


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--source", required=True)
    parser.add_argument("--build", required=True)
    parser.add_argument("--no-python", action="store_true",
                        help="skip the python blocks (a build without the Python module)")
    parser.add_argument("--keep-on-failure", action="store_true",
                        help="keep the scratch folder when a command fails, to look into it")
    parser.add_argument("pages", nargs="*", default=PAGES)
    args = parser.parse_args()
    args.source, args.build = os.path.abspath(args.source), os.path.abspath(args.build)
    used, failures, ran = set(), [], 0
    folder = scratch(args.source, args.build)
    env = environment(args, folder)
    for page in args.pages:
        page_ran, page_failures = run_page(page, args, folder, env, used)
        ran += page_ran
        failures += page_failures
    if args.pages == PAGES:
        for page in LINKS_ONLY:
            with open(os.path.join(args.source, page), encoding="utf-8") as f:
                failures += broken_links(args.source, page, f.read())
        for key in list(EXCLUDED) + list(EXCLUDED_EXACT):
            if key not in used:
                failures.append(f"exclusion `{key}` matches no command any more: remove it")
    for failure in failures:
        print("FAILED: " + failure, file=sys.stderr)
    if failures and args.keep_on_failure:
        print(f"scratch folder kept: {folder}")
    else:
        shutil.rmtree(folder, ignore_errors=True)
    print(f"{ran} commands run, {len(failures)} failed")
    return 1 if failures or ran == 0 else 0


if __name__ == "__main__":
    sys.exit(main())
