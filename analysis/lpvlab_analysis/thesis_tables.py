"""The thesis's timing tables 8.2-8.7 as data, and the 'trend vs thesis' comparison.

Transcribed from the thesis text (/work/shared/seeds/000_002015a09eec5299.txt,
section 8.1). All values are milliseconds measured on the thesis's two
machines ("Intel" and "AMD" setups), with four cascade levels. The absolute
numbers are not comparable with another GPU, so the report compares *shapes*:
each series is divided by its value at a common reference x (the smallest x
present in both), e.g. the 1-iteration propagation time.

Column names in the propagation tables: GS/CS = geometry-shader / compute-shader
implementation, gather (sběr) / scatter (rozptyl) = propagation scheme.
"""
import math
from dataclasses import dataclass, field

from . import summary as S


@dataclass
class ThesisTable:
    number: str            # "8.5"
    caption: str           # original Czech caption
    caption_en: str        # English translation
    x_param: str           # summary.csv parameter column it maps onto
    x_label: str
    x: list                # x values (RSM side length, or iteration count)
    stage: str             # lpvlab stage whose time (time.<stage>.ms) is comparable
    columns: dict = field(default_factory=dict)   # name -> list of ms, same length as x
    applies_to: tuple = () # substrings of propagation.type or occlusion.type it matches ('' = any non-extension type)


_RSM = [32, 64, 128, 256, 512, 1024]
_IT = [1, 2, 4, 8, 16, 32, 64]
_PROP_COLS = ["Intel GS gather", "Intel GS scatter", "Intel CS gather", "Intel CS scatter",
              "AMD GS gather", "AMD GS scatter", "AMD CS gather", "AMD CS scatter"]


def _cols(names, rows):
    return {n: [r[i] for r in rows] for i, n in enumerate(names)}


TABLES = {
    "8.2": ThesisTable(
        "8.2",
        "Tabulka 8.2: Vliv velikosti RSM na čas (v ms) vykreslení všech dlaždic scény na sestavách Intel a AMD.",
        "Table 8.2: Effect of the RSM size on the time (ms) to render all scene tiles, Intel and AMD setups.",
        "param.light_maps.rsm_resolution", "RSM tile side (px)", _RSM, "rsm",
        _cols(["Intel RSM", "Intel RSM Bg", "Intel RSM GV", "AMD RSM", "AMD RSM Bg", "AMD RSM GV"], [
            [1.34, 2.18, 2.69, 2.17, 3.10, 3.54],
            [1.36, 2.20, 2.74, 2.40, 3.32, 3.98],
            [1.38, 2.23, 2.82, 2.47, 3.39, 4.57],
            [1.54, 2.34, 2.98, 2.73, 4.13, 4.72],
            [2.21, 3.35, 4.21, 4.52, 6.66, 7.83],
            [4.85, 7.04, 8.57, 15.13, 24.14, 29.17]])),
    "8.3": ThesisTable(
        "8.3",
        "Tabulka 8.3: Vliv velikosti RSM na čas (v ms) injekce do LPV na sestavě Intel.",
        "Table 8.3: Effect of the RSM size on the time (ms) of injection into the LPV, Intel setup.",
        "param.light_maps.rsm_resolution", "RSM tile side (px)", _RSM, "injection",
        _cols(["Intel GS", "Intel GS Bg", "Intel GS GV", "Intel CS", "Intel CS Bg", "Intel CS GV"], [
            [0.14, 0.42, 0.51, 0.07, 0.11, 0.13],
            [0.15, 0.45, 0.52, 0.07, 0.12, 0.13],
            [0.22, 0.47, 0.63, 0.10, 0.15, 0.23],
            [0.66, 1.06, 1.66, 0.32, 0.41, 0.65],
            [2.56, 2.83, 5.28, 1.36, 1.39, 2.51],
            [13.22, 14.13, 23.87, 6.08, 6.18, 10.39]])),
    "8.4": ThesisTable(
        "8.4",
        "Tabulka 8.4: Vliv velikosti RSM na čas (v ms) injekce do LPV na sestavě AMD.",
        "Table 8.4: Effect of the RSM size on the time (ms) of injection into the LPV, AMD setup.",
        "param.light_maps.rsm_resolution", "RSM tile side (px)", _RSM, "injection",
        _cols(["AMD GS", "AMD GS Bg", "AMD GS GV", "AMD CS", "AMD CS Bg", "AMD CS GV"], [
            [0.30, 0.42, 0.54, 0.21, 0.25, 0.27],
            [0.41, 0.76, 0.53, 0.24, 0.29, 0.47],
            [0.48, 0.71, 0.83, 0.37, 0.37, 0.57],
            [0.71, 0.98, 1.32, 0.43, 0.69, 0.76],
            [1.81, 2.28, 3.95, 1.31, 1.67, 2.87],
            [6.67, 7.18, 15.98, 5.22, 5.54, 11.68]])),
    "8.5": ThesisTable(
        "8.5",
        "Tabulka 8.5: Vliv počtu propagací na čas (v ms) metody LPV bez rozšíření na sestavách Intel a AMD.",
        "Table 8.5: Effect of the number of propagations on the time (ms) of plain LPV (no extensions), Intel and AMD setups.",
        "param.propagation.iterations", "propagation iterations", _IT, "propagation",
        _cols(_PROP_COLS, [
            [0.70, 3.92, 0.97, 1.22, 0.88, 5.21, 5.20, 7.17],
            [1.33, 7.83, 1.24, 1.83, 1.64, 10.16, 6.91, 10.89],
            [2.53, 15.46, 1.77, 2.94, 3.42, 20.43, 10.31, 18.24],
            [4.93, 27.57, 2.92, 4.95, 5.93, 41.98, 17.10, 32.69],
            [9.91, 61.94, 5.23, 9.47, 12.24, 97.27, 30.61, 61.99],
            [20.71, 127.47, 9.51, 18.71, 25.35, 239.57, 57.64, 128.41],
            [39.55, 257.73, 18.53, 36.69, 52.67, 554.78, 111.43, 237.97]]),
        applies_to=("",)),
    "8.6": ThesisTable(
        "8.6",
        "Tabulka 8.6: Vliv počtu propagací na čas (v ms) metody LPV s použitím mřížky zastínění na sestavách Intel a AMD.",
        "Table 8.6: Effect of the number of propagations on the time (ms) of LPV with the geometry (occlusion) volume, Intel and AMD setups.",
        "param.propagation.iterations", "propagation iterations", _IT, "propagation",
        _cols(_PROP_COLS, [
            [1.38, 9.25, 1.69, 2.04, 1.07, 5.24, 6.25, 7.42],
            [2.56, 18.84, 2.62, 3.24, 1.83, 10.73, 9.19, 11.32],
            [2.67, 18.90, 2.69, 3.39, 3.35, 20.69, 14.84, 19.31],
            [5.12, 37.68, 4.36, 5.89, 6.49, 42.11, 25.96, 34.54],
            [10.73, 74.59, 9.38, 12.00, 13.17, 96.95, 40.10, 65.45],
            [21.41, 150.34, 16.38, 22.62, 26.97, 238.77, 92.74, 127.58],
            [41.92, 310.02, 31.08, 45.40, 53.54, 556.41, 181.61, 251.09]]),
        applies_to=("occlusion", "geometry", "gv")),
    "8.7": ThesisTable(
        "8.7",
        "Tabulka 8.7: Vliv počtu propagací na čas (v ms) metody LPV s použitím usměrnění propagace na sestavách Intel a AMD.",
        "Table 8.7: Effect of the number of propagations on the time (ms) of LPV with directed (steered) propagation, Intel and AMD setups.",
        "param.propagation.iterations", "propagation iterations", _IT, "propagation",
        _cols(_PROP_COLS, [
            [0.81, 5.16, 1.19, 1.26, 1.05, 5.24, 5.33, 7.34],
            [1.53, 8.77, 1.24, 2.47, 1.86, 10.44, 7.06, 11.14],
            [2.83, 18.73, 1.82, 2.96, 3.45, 20.63, 10.67, 18.86],
            [6.23, 49.35, 3.23, 5.19, 6.91, 42.14, 17.46, 34.41],
            [11.39, 71.55, 5.17, 9.91, 13.84, 94.53, 31.51, 64.69],
            [22.47, 143.27, 9.84, 18.71, 29.02, 233.86, 59.46, 126.02],
            [43.68, 287.82, 19.38, 36.22, 58.63, 542.81, 114.69, 247.45]]),
        applies_to=("direct", "steer", "usmer")),
}


def _type_matches(table, prop_type):
    """Does a propagation.type name correspond to the table's method?

    8.6/8.7 match by keyword; 8.5 ("no extension") matches types that match
    none of the extension tables' keywords.
    """
    t = str(prop_type).lower()
    if table.applies_to == ("",) or not table.applies_to:
        if table.number != "8.5":
            return True
        ext = TABLES["8.6"].applies_to + TABLES["8.7"].applies_to
        return not any(k in t for k in ext)
    return any(k in t for k in table.applies_to)


def _methods(agg):
    """Per row, the names that say which method it ran: propagation.type, and occlusion.type
    where the sweep records it (the geometry volume of 8.6 is an occlusion strategy)."""
    names = agg["param.propagation.type"].astype(str)
    if "param.occlusion.type" in agg.columns:
        names = names + " " + agg["param.occlusion.type"].astype(str)
    return list(names)


def applicable_tables(agg):
    """Tables whose x parameter varies in the sweep (numerically) and whose
    method matches at least one configuration, with the matching rows:
    list of (ThesisTable, DataFrame)."""
    out = []
    for key, tab in TABLES.items():
        if tab.x_param not in agg.columns or agg[tab.x_param].nunique() < 2:
            continue
        rows = agg
        if "param.propagation.type" in agg.columns and tab.stage == "propagation":
            rows = agg[[_type_matches(tab, v) for v in _methods(agg)]]
        col = S.time_col(tab.stage)
        if len(rows) and col in rows.columns and rows[col].notna().any():
            out.append((tab, rows))
    return out


def measured_series(tab, rows):
    """This machine's curves for a table: {series name: (x list, ms list)}.

    One series per variant; when several configurations share a variant and x
    (other parameters varied too), their median is used.
    """
    col = S.time_col(tab.stage)
    series = {}
    for variant, g in rows.groupby("variant", sort=True):
        m = g.groupby(tab.x_param)[col].median().dropna().sort_index()
        if len(m) >= 2:
            series[f"lpvlab {variant}"] = ([float(v) for v in m.index], [float(v) for v in m.values])
    return series


def normalise(xs, ys, x_ref):
    """Divide ys by the y at x_ref (None if x_ref is absent or that y is 0)."""
    for x, y in zip(xs, ys):
        if x == x_ref and y and not math.isnan(y):
            return [v / y for v in ys]
    return None


def reference_x(tab, measured):
    """Smallest x present both in the thesis table and in every measured series
    (falls back to the smallest x common to the thesis and any series)."""
    common = set(tab.x)
    for xs, _ in measured.values():
        common &= set(xs)
    if not common:
        for xs, _ in measured.values():
            if set(tab.x) & set(xs):
                return min(set(tab.x) & set(xs))
        return None
    return min(common)
