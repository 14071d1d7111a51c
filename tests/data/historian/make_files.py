#!/usr/bin/env python3
"""Writes the historian exports of tests/app (issue #43): each file a shift of the same seven tags
as PI, WinCC and Excel write them. Run from this folder: python3 make_files.py"""
import datetime as dt
import math

TAGS = ["HDT_TT101.PV", "FEED_WT201.PV", "NIR_XIN.PV", "HALL_TT301.PV", "HALL_MT302.PV", "NIR_XOUT.PV",
        "WIN_TT401.PV"]
START = dt.datetime(2025, 6, 3, 8, 0, 0)


def values(i, feed=None):
    """The seven tags at second i of a shift."""
    return [170 + 5 * math.sin(i / 300), 6200 + 100 * math.sin(i / 700) if feed is None else feed,
            22 + 0.5 * math.sin(i / 900), 24, 55, 13 + 0.2 * math.sin(i / 400), 55]


def cells(vals, comma=False, thousands=None):
    out = []
    for v in vals:
        s = "%.3f" % v
        whole, frac = s.split(".")
        if thousands and len(whole) > 3:
            whole = whole[:-3] + thousands + whole[-3:]
        out.append(whole + ("," if comma else ".") + frac)
    return out


def write(name, text, encoding="utf-8"):
    with open(name, "wb") as f:
        f.write(text.encode(encoding) if isinstance(text, str) else text)


def shift(stamp, n=400, delimiter=";", comma=False, thousands=None, header="Timestamp", units=None,
          cell=None, start=START):
    lines = [delimiter.join([header] + TAGS)]
    if units:
        lines.append(delimiter.join([""] + units))
    for i in range(n):
        row = cells(values(i), comma, thousands)
        if cell:
            row = cell(i, row)
        lines.append(delimiter.join([stamp(start + dt.timedelta(seconds=i), i)] + row))
    return "\n".join(lines) + "\n"


iso = lambda t, i: t.strftime("%Y-%m-%d %H:%M:%S")

# 1. Excel serial days from midnight: the first stamp is the whole number 45811.
def excel(t, i):
    days = 45811 + i / 86400.0
    return ("%.10f" % days).rstrip("0").rstrip(".")
write("excel_midnight.csv", shift(excel, delimiter=",", header="Date", start=dt.datetime(2025, 6, 3)))

# 2. A shift to read with a mapping that misspells an optional column's tag.
write("iso_shift.csv", shift(iso))

# 3. German numbers: a start-up ramp below 1,000 kg/h (no mark), then 6.497 (a thousands point);
# decimal commas appear only after the first 200 rows.
def german(i, row):
    v = values(i)
    feed = 600 + i if i < 300 else 6497
    row = [str(round(v[0])) if i < 250 else cells([v[0]], True)[0],
           "{:,}".format(feed).replace(",", "."), str(round(v[2])), "24", "55",
           str(round(v[5])) if i < 250 else cells([v[5]], True)[0], "55"]
    return row
write("german_thousands.csv", shift(iso, n=600, cell=german))

# 4. Two rows swapped at lines 101/102; and daylight saving ending (02:59:59 -> 02:00:00 local).
text = shift(iso).split("\n")
text[100], text[101] = text[101], text[100]
write("swapped_rows.csv", "\n".join(text))
def dst(t, i):
    base = dt.datetime(2025, 10, 26, 2, 50, 0) + dt.timedelta(seconds=i)
    return (base - dt.timedelta(hours=1) if i >= 600 else base).strftime("%Y-%m-%d %H:%M:%S")
write("dst_fall_back.csv", shift(dst, n=1200))

# 5. PI DataLink: 03-Jun-2025 08:00:00, tab-separated, digital states in cells.
def pi_states(i, row):
    if i in (40, 41):
        row[1] = "Shutdown"
    if i == 90:
        row[5] = "Comm Fail"
    return row
write("pi_datalink.csv", shift(lambda t, i: t.strftime("%d-%b-%Y %H:%M:%S"), delimiter="\t", cell=pi_states))

# US locale: 6/3/2025 11:55:00 PM, across midnight (the column decides month/day); one day only.
us = lambda t, i: "%d/%d/%d %d:%02d:%02d %s" % (t.month, t.day, t.year, (t.hour + 11) % 12 + 1, t.minute,
                                                t.second, "AM" if t.hour < 12 else "PM")
write("us_locale.csv", shift(us, delimiter=",", start=dt.datetime(2025, 6, 3, 23, 55, 0)))
write("us_locale_one_day.csv", shift(us, delimiter=","))

# Encodings: Windows-1252 (a units row with °C, a German header), UTF-16 LE with a byte-order
# mark, UTF-16 BE without one.
units = ["°C", "kg/h", "%", "°C", "%", "%", "°C"]
write("windows1252.csv", shift(lambda t, i: t.strftime("%d.%m.%Y %H:%M:%S"), comma=True, thousands=".",
                               header="Zeitstempel", units=units), "cp1252")
write("utf16le_bom.csv", "\ufeff" + shift(iso, delimiter="\t"), "utf-16-le")
write("utf16be.csv", shift(iso, comma=True), "utf-16-be")

# 6. A contract-form batch with an impossible outlet moisture on line 7 (column 12), and one
# whose inlet moisture the line model cannot take (95 % wb on line 5).
HEADER = ("time_s,T_hot_sp_C,T_hot_C,air_speed_m_s,feed_kg_h,X_in_pct,T_in_C,T_amb_C,RH_amb_pct,"
          "X_hdt_pct,T_hdt_C,X_out_pct,T_out_C")
def contract(n, change):
    rows = [HEADER]
    for i in range(n):
        r = [i, 170, 169.5, 16, 6200, 22, 25, 24, 55, 14, 58, 12.8, 55.2]
        change(i, r)
        rows.append(",".join("%g" % v for v in r))
    return "\n".join(rows) + "\n"
write("impossible.csv", contract(30, lambda i, r: r.__setitem__(11, 140) if i == 5 else None))
write("simulate_out_of_range.csv", contract(120, lambda i, r: r.__setitem__(5, 95) if i == 3 else None))

# Issue #72. 12. Excel cells holding a time of day alone (a fraction of a day, as Excel's General
# format writes it: ten significant digits, an exponent below 0.0001), across midnight on line 602.
def excel_time(t, i):
    fraction = ((23 * 3600 + 50 * 60 + i) % 86400) / 86400.0
    return "%.9E" % fraction if 0 < fraction < 1e-4 else "%.10g" % fraction
write("excel_time_of_day.csv", shift(excel_time, n=1200, delimiter=",", header="Time"))

# 13. A step back of one hour on 3 June, which is no night daylight saving ends in.
def hour_back_in_june(t, i):
    base = dt.datetime(2025, 6, 3, 2, 50, 0) + dt.timedelta(seconds=i)
    return (base - dt.timedelta(hours=1) if i >= 600 else base).strftime("%Y-%m-%d %H:%M:%S")
write("hour_back_in_june.csv", shift(hour_back_in_june, n=1200))

# 16. A pipe-delimited export; and 1 March written as 29 February 2025 (line 302).
write("pipe_delimited.csv", shift(iso, delimiter="|"))
def february_29(t, i):
    return iso(t, i).replace("2025-03-01", "2025-02-29")
write("impossible_date.csv", shift(february_29, start=dt.datetime(2025, 2, 28, 23, 55, 0)))
