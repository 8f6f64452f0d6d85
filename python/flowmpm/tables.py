"""Tables (timeseries.csv, sweep.csv, a sweep's joined table) as a pandas
DataFrame, or without pandas as a numpy structured array.

A column whose every value is a number (or empty: NaN) is float; any other
is text. Column names are the files' own ("block.stress_yy").
"""
import csv

import importlib.util

import numpy as np


def _number(text):
    try:
        return float(text) if text != "" else float("nan")
    except ValueError:
        return None


def make_table(columns, use_pandas=None, text=()):
    """A table from {name: list of values} (numbers, text or None): a
    DataFrame where pandas is installed (or `use_pandas`), else a numpy
    structured array; float columns where every value is a number, except
    the columns named in `text`."""
    names = list(columns)
    typed = {}
    for name, values in columns.items():
        numbers = [_number(v) if isinstance(v, str) else (float("nan") if v is None else v) for v in values]
        if name not in text and all(isinstance(n, (int, float)) and not isinstance(n, bool) for n in numbers):
            typed[name] = np.array(numbers, dtype=float)
        else:
            typed[name] = np.array(["" if v is None else str(v) for v in values], dtype=object)
    if use_pandas is None:
        use_pandas = importlib.util.find_spec("pandas") is not None
    if use_pandas:
        try:
            import pandas  # only here: importing it takes seconds
        except ImportError:
            raise ImportError("a DataFrame needs pandas (Debian's python3-pandas); without it, use_pandas=False "
                              "gives a numpy structured array") from None
        return pandas.DataFrame(typed, columns=names)
    length = len(next(iter(typed.values()))) if typed else 0
    table = np.empty(length, dtype=[(n, typed[n].dtype) for n in names])
    for n in names:
        table[n] = typed[n]
    return table


def read_csv(path, use_pandas=None):
    """A CSV file with a header line as a table (make_table)."""
    with open(path, newline="", encoding="utf-8") as f:
        rows = list(csv.reader(f))
    if not rows:
        raise ValueError(f"{path}: empty, expected a header line")
    header, body = rows[0], rows[1:]
    return make_table({name: [row[i] if i < len(row) else "" for row in body] for i, name in enumerate(header)},
                      use_pandas)


def columns_of(table):
    """The column names of a table (DataFrame or structured array)."""
    return list(table.columns) if hasattr(table, "columns") else list(table.dtype.names)
