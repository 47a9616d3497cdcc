"""The rooms of app/ include only the rooms below them, as docs/development.md says (issue 41, 1).

Reads the block between the `app-rooms` markers of docs/development.md (`ROOM -> BELOW, ...`, one
room a line; a room names every room it may include) and every C++ file in app/ROOM/, and names
each `#include "app/OTHER/..."` of a room not listed for it, as FILE:LINE, one a line. A file
directly in app/, or a folder the block does not name, is named too: every file keeps to a room.

Usage: app_rooms.py --source DIR [--page docs/development.md]
"""

import argparse
import re
import sys
from pathlib import Path

BEGIN = "<!-- app-rooms: begin -->"
END = "<!-- app-rooms: end -->"


def rooms_from_page(text):
    """{room: set of rooms it may include} from the page's block."""
    block = text.split(BEGIN, 1)[1].split(END, 1)[0]
    rooms = {}
    for line in block.strip().strip("`").strip().splitlines():
        room, _, below = line.partition("->")
        rooms[room.strip()] = {name.strip() for name in below.split(",") if name.strip()}
    return rooms


def problems(source, rooms):
    found = []
    app = source / "app"
    for path in sorted(app.rglob("*")):
        if path.suffix not in (".cpp", ".hpp"):
            continue
        relative = path.relative_to(source)
        room = path.relative_to(app).parts[0] if len(path.relative_to(app).parts) > 1 else None
        if room not in rooms:
            found.append(f"{relative}: in no room of the page's app-rooms block")
            continue
        for number, line in enumerate(path.read_text().splitlines(), 1):
            match = re.match(r'\s*#\s*include\s+"app/([^/"]+)/', line)
            if match and match.group(1) != room and match.group(1) not in rooms[room]:
                found.append(f"{relative}:{number}: {room} includes app/{match.group(1)}/, "
                             f"not a room below it ({room} -> {', '.join(sorted(rooms[room]))})")
    return found


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--source", type=Path, required=True)
    parser.add_argument("--page", type=Path)
    args = parser.parse_args()
    page = args.page or args.source / "docs" / "development.md"
    found = problems(args.source, rooms_from_page(page.read_text()))
    for line in found:
        print(line)
    if found:
        return 1
    print("every include of app/ keeps to the rooms below it")
    return 0


if __name__ == "__main__":
    sys.exit(main())
