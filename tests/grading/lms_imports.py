"""What Canvas's and Moodle's gradebook imports make of our files, as their
own code reads them, for tests/grading/test_lms_export.cpp.

Neither import runs without its site's database, so each rule below is the
import's own, written again from the file and function cited. Each command
takes the gradebook as it is before the import (JSON: student -> column ->
grade) and the files imported one after the other, and prints, as JSON,
the gradebook after them, or the error that makes the import refuse a file.

  lms_imports.py canvas GRADEBOOK_JSON FILE...
  lms_imports.py moodle GRADEBOOK_JSON BY FILE...   (BY: "Email address" or
                                                     "ID number")
"""

import csv
import json
import re
import sys


class Refused(Exception):
    pass


def canvas_student_columns(h):
    """How many student columns Canvas finds, and where ID is; refuses a
    header as it does. instructure/canvas-lms lib/gradebook_importer.rb:
    header? -> row_has_student_headers?, update_column_count,
    last_student_info_column."""
    first_last_ok = len(h) > 4 and "LastName" in h[0] and "FirstName" in h[1] and "ID" in h[2]
    if not ((len(h) > 3 and "Student" in h[0] and "ID" in h[1]) or first_last_ok):
        raise Refused("Invalid header row")
    first_last = h[0] == "LastName" and h[1] == "FirstName"
    n = 4 if first_last else 3
    cols = n

    def at(i, pattern):
        return i < len(h) and re.search(pattern, h[i]) is not None

    if at(n - 1, r"SIS\s+Login\s+ID"):
        cols += 1
    elif at(n - 1, r"SIS\s+User\s+ID") and at(n, r"SIS\s+Login\s+ID"):
        i = 1 if at(n + 1, r"Integration\s+ID") else 0
        cols += 2 + i
        if at(n + 1 + i, r"Root\s+Account"):
            cols += 1
    if cols - 1 >= len(h) or "Section" not in h[cols - 1]:
        raise Refused("Invalid header row")
    return cols, n - 2


# lib/gradebook_importer.rb, NON_ASSIGNMENT_COLUMN_HEADERS and
# strip_non_assignment_columns: a header holding one of these is dropped.
CANVAS_TOTALS = ["Current Score", "Current Points", "Current Grade", "Final Score",
                 "Final Points", "Final Grade", "Override Score", "Override Grade",
                 "Override Status"]


def canvas(book, files):
    for f in files:
        rows = list(csv.reader(open(f, newline="", encoding="utf-8")))
        # csv_stream: skip_lines /^[;, ]+$/.
        rows = [r for r in rows if not re.fullmatch(r"[;, ]*", ",".join(r))]
        h = rows[0]
        cols, id_col = canvas_student_columns(h)
        assignments = [(i, t) for i, t in enumerate(h)
                       if i >= cols and not any(s in t for s in CANVAS_TOTALS)]
        for r in rows[1:]:
            # check_for_non_student_row: Points Possible, Muted rows.
            if "Points Possible" in r[0]:
                continue
            if all(re.fullmatch(r"\s*(Muted|Manual Posting.*)?\s*", c, re.I) for c in r):
                continue
            # process_student: by ID (then SIS ids, name: not modelled).
            student = book.setdefault(r[id_col], {})
            for i, title in assignments:
                grade = (r[i] if i < len(r) else "").strip()
                # process_submissions takes the cell as the grade;
                # no_change_to_value? counts blank or "-" over a score as a
                # change, which the upload then saves as no score.
                if grade in ("", "-"):
                    student.pop(title, None)
                else:
                    student[title] = grade
    return book


def moodle(book, by, files):
    """grade/import/csv/classes/load_data.php, prepare_import_grade_data,
    with "Map from" BY and "Map to" the same user field; every other column
    mapped to the grade item of its name."""
    known = set(book)
    for f in files:
        rows = list(csv.reader(open(f, newline="", encoding="utf-8")))
        header = [c.strip() for c in rows[0]]  # trim_headers
        if by not in header:
            raise Refused("no column " + by)
        key = header.index(by)
        pending = {}
        student = None
        for r in rows[1:]:
            if len(r) <= 1:  # "There is no data on this line"
                continue
            value = r[key].strip()
            # map_user_data_with_value: a blank identifier is skipped, so
            # the row's grades go to the student of the row before.
            if value:
                if value not in known:  # check_user_exists
                    raise Refused("usermappingerror: " + value)
                student = value
            if student is None:
                raise Refused("usermappingerrorusernotfound")
            for i, name in enumerate(header):
                if i == key or name in ("Email address", "ID number"):
                    continue
                cell = r[i].strip() if i < len(r) else ""
                # update_grade_item: '' and '-' are a null grade, which
                # grade/import/lib.php grade_import_commit writes over the
                # grade the student has.
                if cell in ("", "-"):
                    pending.setdefault(student, {})[name] = None
                    continue
                # insert_grade_record: above gradepointmax (100) the whole
                # import stops.
                if float(cell) > 100:
                    raise Refused("gradevaluetoobig")
                pending.setdefault(student, {})[name] = cell
        for student, grades in pending.items():
            for name, grade in grades.items():
                if grade is None:
                    book[student].pop(name, None)
                else:
                    book[student][name] = grade
    return book


def main():
    try:
        book = json.loads(sys.argv[2])
        if sys.argv[1] == "canvas":
            print(json.dumps(canvas(book, sys.argv[3:]), sort_keys=True))
        else:
            print(json.dumps(moodle(book, sys.argv[3], sys.argv[4:]), sort_keys=True))
    except Refused as e:
        print(json.dumps({"refused": str(e)}))


main()
