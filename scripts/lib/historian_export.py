#!/usr/bin/env python3
"""Writes a folder of contract batch files as one historian export, as a plant's historian gives
it (issue #72's click-through "with a historian file opened through the mapping dialog"): tag
names, ISO time stamps, semicolons and decimal commas, the batches one after another with a
five-minute line stop (feed 0) between them, and beside it the column mapping the dialog proposes.
    python3 scripts/lib/historian_export.py BATCH_FOLDER OUT.csv OUT_MAPPING.json [BATCHES]"""
import datetime
import glob
import json
import os
import sys

TAGS = [("T_hot_sp_C", "HDT_TIC101.SP"), ("T_hot_C", "HDT_TT101.PV"), ("air_speed_m_s", "HDT_ST102.PV"),
        ("feed_kg_h", "FEED_WT201.PV"), ("X_in_pct", "NIR_IN.PV"), ("T_in_C", "FEED_TT202.PV"),
        ("T_amb_C", "HALL_TT301.PV"), ("RH_amb_pct", "HALL_MT302.PV"), ("X_hdt_pct", "HDT_MT103.PV"),
        ("T_hdt_C", "HDT_TT104.PV"), ("X_out_pct", "NIR_OUT.PV"), ("T_out_C", "WIN_TT401.PV")]
STOP_S = 300


def rows_of(path):
    with open(path, encoding="utf-8") as f:
        lines = [l.rstrip("\n") for l in f if not l.startswith("#")]
    header = lines[0].split(",")
    return [dict(zip(header, l.split(","))) for l in lines[1:] if l]


def main(folder, out_csv, out_mapping, batches=4):
    files = sorted(glob.glob(os.path.join(folder, "*.csv")))[: int(batches)]
    t = datetime.datetime(2025, 6, 3, 6, 0, 0)
    with open(out_csv, "w", encoding="utf-8") as out:
        out.write(";".join(["Timestamp"] + [tag for _, tag in TAGS]) + "\n")
        for n, f in enumerate(files):
            rows = rows_of(f)
            for r in rows:
                cells = [t.strftime("%Y-%m-%d %H:%M:%S")] + [r.get(col, "").replace(".", ",") for col, _ in TAGS]
                out.write(";".join(cells) + "\n")
                t += datetime.timedelta(seconds=1)
            if n + 1 < len(files):  # the line stopped between two runs: no feed, the rest as it was
                last = rows[-1]
                for _ in range(STOP_S):
                    cells = [t.strftime("%Y-%m-%d %H:%M:%S")] + [
                        "0" if col == "feed_kg_h" else last.get(col, "").replace(".", ",") for col, _ in TAGS]
                    out.write(";".join(cells) + "\n")
                    t += datetime.timedelta(seconds=1)
    mapping = {"time_s": {"header": "Timestamp", "format": "iso8601"}}
    mapping.update({col: tag for col, tag in TAGS})
    with open(out_mapping, "w", encoding="utf-8") as m:
        json.dump(mapping, m, indent=2)
        m.write("\n")


if __name__ == "__main__":
    main(*sys.argv[1:])
