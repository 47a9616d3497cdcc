"""The module link graph docs/development.md draws is the one CMake links (issue 41, 1).

Configures the project into a scratch folder with `cmake --graphviz` (product targets only: no
tests, benchmarks or fuzzers), reads each product target's direct links from the graph, and
compares them with the block between the `link-graph` markers of docs/development.md. Either
side's extra or missing links are named, one a line, with the line the page should have.

Usage: link_graph.py --cmake CMAKE --source DIR [--page docs/development.md] [--dot FILE]
(--dot reads a graph already written instead of configuring.)
"""

import argparse
import re
import subprocess
import sys
import tempfile
from pathlib import Path

BEGIN = "<!-- link-graph: begin -->"
END = "<!-- link-graph: end -->"


def short(name):
    """curvefold_fit -> fit; PkgConfig::IMGUI -> IMGUI; TBB::tbb -> TBB; plain names stay."""
    if name.startswith("curvefold_"):
        return name[len("curvefold_"):]
    if name.startswith("PkgConfig::"):
        return name[len("PkgConfig::"):]
    return name.split("::")[0]


def ours(name):
    return name in ("curvefold", "_curvefold") or name.startswith("curvefold_")


def links_from_dot(text):
    """{target: (set of our libraries, set of external packages)} for each of our targets."""
    # A label is the target's name, then for an imported one "\n(its full name)".
    labels = {node: label.split("\\n")[0]
              for node, label in re.findall(r'"(node\d+)" \[ label = "([^"]+)"', text)}
    graph = {label: (set(), set()) for label in labels.values() if ours(label)}
    for source, target in re.findall(r'"(node\d+)" -> "(node\d+)"', text):
        a, b = labels[source], labels[target]
        if not ours(a) or b.startswith("/") or b.startswith("-"):
            continue  # a package's own links, or a plain library file a package names
        graph[a][0 if ours(b) else 1].add(short(b))
    return {short(a): links for a, links in graph.items()}


def line(target, links):
    inside, outside = links
    text = target
    if inside:
        text += " -> " + ", ".join(sorted(inside))
    if outside:
        text += " | " + ", ".join(sorted(outside, key=str.lower))
    return text


def links_from_page(page):
    text = page.read_text()
    if BEGIN not in text or END not in text:
        sys.exit(f"{page}: no block between {BEGIN} and {END}")
    block = text.split(BEGIN, 1)[1].split(END, 1)[0]
    drawn = {}
    items = lambda text: {x.strip() for x in text.split(",") if x.strip()}
    for row in block.splitlines():
        row = row.strip()
        if not row or row.startswith("```"):
            continue
        left, _, outside = row.partition(" | ")
        target, _, inside = left.partition(" -> ")
        drawn[target.strip()] = (items(inside), items(outside))
    return drawn


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--cmake", default="cmake")
    parser.add_argument("--source", type=Path, required=True)
    parser.add_argument("--page", type=Path)
    parser.add_argument("--dot", type=Path)
    args = parser.parse_args()
    page = args.page or args.source / "docs" / "development.md"
    if args.dot:
        dot = args.dot.read_text()
    else:
        with tempfile.TemporaryDirectory(prefix="curvefold-link-graph-") as scratch:
            graph = Path(scratch) / "links.dot"
            done = subprocess.run(
                [args.cmake, "-S", str(args.source), "-B", str(Path(scratch) / "build"),
                 f"--graphviz={graph}", "-DCURVEFOLD_BUILD_TESTS=OFF",
                 "-DCURVEFOLD_BUILD_BENCHMARKS=OFF", "-DCURVEFOLD_FUZZ=OFF",
                 "-DCURVEFOLD_SANITIZE=OFF", "-DCURVEFOLD_TSAN=OFF", "-DCURVEFOLD_PYTHON=ON"],
                capture_output=True, text=True)
            if done.returncode != 0:
                sys.exit("cmake failed to configure:\n" + done.stdout + done.stderr)
            dot = graph.read_text()
    linked = links_from_dot(dot)
    drawn = links_from_page(page)
    problems = []
    for target in sorted(set(linked) | set(drawn)):
        if target not in drawn:
            problems.append(f"{page.name} lacks {target}: `{line(target, linked[target])}`")
        elif target not in linked:
            problems.append(f"{page.name} draws {target}, which CMake does not build")
        elif linked[target] != drawn[target]:
            problems.append(f"{page.name} draws `{line(target, drawn[target])}`, "
                            f"CMake links `{line(target, linked[target])}`")
    for problem in problems:
        print(problem)
    if problems:
        sys.exit(1)
    print(f"{len(linked)} targets, links as {page.name} draws them")


if __name__ == "__main__":
    main()
