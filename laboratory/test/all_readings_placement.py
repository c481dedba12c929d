#!/usr/bin/env python3
"""write_all_readings_certified.py puts a set's row and statement into conjectures.md the first
time (set 2 before set 3), replaces them afterwards, says "all N starts" once every shard is in,
and refuses a page that has neither set's."""
import datetime
import os
import re
import sys

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "laboratory", "scripts"))
import write_all_readings_certified as writer  # noqa: E402


def facts(indices, starts):
    return dict(indices=indices, starts=starts, limit=7 * starts, seconds=1234.4, dates=[datetime.date(2026, 12, 4)], total=5563240,
                fewest="4 under 36 readings")


def spans(text, set_number):
    rows = [m.start() for m in re.finditer(writer.row_pattern(set_number), text, flags=re.S)]
    clauses = [m.start() for m in re.finditer(writer.clause_pattern(set_number), text, flags=re.S)]
    assert len(rows) == 1 and len(clauses) == 1, (set_number, rows, clauses)
    return rows[0], clauses[0]


def main():
    # The page as it was before set 2's first shard (once set 2 is written up, its parts are taken out).
    page = open(writer.CONJECTURES_MD).read()
    page = re.sub(writer.row_pattern(2) + "\n", "", page, flags=re.S)
    page = re.sub(writer.clause_pattern(2) + ", ", "", page, flags=re.S)
    spans(page, 3)
    assert not re.search(writer.row_pattern(2), page) and not re.search(writer.clause_pattern(2), page, flags=re.S)

    first = writer.conjectures_text(page, 2, facts([0], 20480))
    row2, clause2 = spans(first, 2)
    row3, clause3 = spans(first, 3)
    assert row2 < row3 and clause2 < clause3, "set 2's parts are not before set 3's"
    assert first[row2:row3].count("\n") == 1, "set 2's row is not the line before set 3's"
    assert "set 2's shard 0 of 64 (20,480 of its 5,563,240 starts; 143,360 runs at the limit" in first
    assert "| 12 random integer points, set 2, under all 36 readings, shard 0 of 64 (run 2026-12-04;" in first
    assert first.replace(first[row2:row3], "").replace(first[clause2:clause3], "") == page, "more than set 2 changed"

    second = writer.conjectures_text(first, 2, facts([0, 1, 2], 61440))
    spans(second, 2)
    assert "set 2's shards 0 to 2 of 64 (61,440 of its" in second and "20,480 of its" not in second

    # Once every shard is in, the statement says so.
    whole = writer.conjectures_text(second, 2, facts(list(range(64)), 5563240))
    spans(whole, 2)
    assert "set 2's shards 0 to 63 of 64 (all 5,563,240 starts; 38,942,680 runs at the limit" in whole
    assert writer.starts_words(5563240, 5563240, "the") == "all 5,563,240 starts"
    assert writer.starts_words(20480, 5563240, "the") == "20,480 of the 5,563,240 starts"

    # Without set 3's parts, set 3's go after set 2's.
    lone = re.sub(writer.row_pattern(3) + "\n", "", second, flags=re.S)
    lone = re.sub(", " + writer.clause_pattern(3), "", lone, flags=re.S)
    back = writer.conjectures_text(lone, 3, facts([5], 20480))
    row2, clause2 = spans(back, 2)
    row3, clause3 = spans(back, 3)
    assert row2 < row3 and clause2 < clause3, "set 3's parts are not after set 2's"

    neither = re.sub(writer.row_pattern(2) + "\n", "", lone, flags=re.S)
    try:
        writer.conjectures_text(neither, 3, facts([5], 20480))
    except writer.Disagree as e:
        assert "neither set 3's certified row nor set 2's" in str(e), e
    else:
        raise AssertionError("a page with neither set's row was accepted")
    print("placement: set 2 before set 3, replaced once placed, whole once complete, refused with neither")


if __name__ == "__main__":
    main()
