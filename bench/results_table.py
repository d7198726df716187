"""The table a bench script ends with: rows (dicts of strings, every row with the first row's keys)
written to a CSV file and printed as a Markdown table."""
import csv


def write_table(rows, path):
    columns = list(rows[0].keys())
    with open(path, "w", newline="") as out:
        writer = csv.DictWriter(out, fieldnames=columns)
        writer.writeheader()
        writer.writerows(rows)
    print("| " + " | ".join(columns) + " |")
    print("|" + "---|" * len(columns))
    for row in rows:
        print("| " + " | ".join(row[c] for c in columns) + " |")
