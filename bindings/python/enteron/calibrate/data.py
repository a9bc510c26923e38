# SPDX-License-Identifier: Apache-2.0
"""Reference data: what was measured, when, and how well (docs/calibration.md, "The data file").

A CSV file with a header line and one row per measured value; lines starting with # are
comments:

    measurement,t_s,value,sigma
    tip_z,0.10,-0.0213,0.0005
    tip_z,0.20,-0.0391,0.0005

measurement names one of the experiment's measurements, t_s the simulated time of the
value (s, from the start of the experiment; between two steps the simulation is
interpolated linearly), value is in the measurement's unit (m or N), and sigma (optional
column) is its standard deviation in the same unit. Every number must be finite: a NaN, an
empty field, a time past the experiment's end or a name the experiment does not know is
refused with the file and line.
"""
import csv
import math

import numpy as np

from .experiment import CalibrationError

REQUIRED_COLUMNS = ("measurement", "t_s", "value")


class Data:
    """Rows of reference data, in file order: names (measurement of each row), times_s,
    values, sigmas (one per row, or None when the noise is not given and the fit estimates
    its level), lines (the file line of each row, for messages), file."""

    def __init__(self, names, times_s, values, sigmas, lines, file):
        self.names = list(names)
        self.times_s = np.asarray(times_s, dtype=np.float64)
        self.values = np.asarray(values, dtype=np.float64)
        self.sigmas = None if sigmas is None else np.asarray(sigmas, dtype=np.float64)
        self.lines = list(lines)
        self.file = file

    def __len__(self):
        return len(self.names)

    def requests(self):
        """(measurement name, t_s) of every row: what a simulation must predict, in this order."""
        return list(zip(self.names, self.times_s.tolist()))


def _field(text, column, where, low=None, positive=False):
    try:
        value = float(text)
    except ValueError:
        raise CalibrationError("%s: %s %r is not a number" % (where, column, text)) from None
    if not math.isfinite(value):
        raise CalibrationError("%s: %s is %s: every value must be a finite number" % (where, column, text.strip()))
    if positive and not value > 0:
        raise CalibrationError("%s: %s must be > 0, got %s" % (where, column, text.strip()))
    if low is not None and value < low:
        raise CalibrationError("%s: %s must be >= %g, got %s" % (where, column, low, text.strip()))
    return value


def load(path, experiment):
    """Reads and checks a data file against the experiment's measurements and duration."""
    try:
        with open(path, newline="", encoding="utf-8") as file:
            lines = [(number, line) for number, line in enumerate(file, start=1)
                     if line.strip() and not line.lstrip().startswith("#")]
    except OSError as error:
        raise CalibrationError("%s: cannot read the data: %s" % (path, error.strerror or error)) from None
    except UnicodeDecodeError as error:
        raise CalibrationError("%s: not a text (UTF-8) file: %s" % (path, error)) from None
    if not lines:
        raise CalibrationError("%s: no header and no data" % path)
    rows = list(csv.reader(line for _, line in lines))
    header = [column.strip() for column in rows[0]]
    where = "%s line %d" % (path, lines[0][0])
    if tuple(header[:3]) != REQUIRED_COLUMNS or header[3:] not in ([], ["sigma"]):
        raise CalibrationError("%s: the header must be %s[,sigma], got %s"
                               % (where, ",".join(REQUIRED_COLUMNS), ",".join(header)))
    with_sigma = len(header) == 4
    names, times, values, sigmas, numbers = [], [], [], [], []
    seen = {}
    end = experiment_end(experiment)
    for (number, _), row in zip(lines[1:], rows[1:]):
        where = "%s line %d" % (path, number)
        if len(row) != len(header):
            raise CalibrationError("%s: %d field(s) for the %d columns %s" % (where, len(row), len(header), ",".join(header)))
        name = row[0].strip()
        if name not in experiment.measurements:
            raise CalibrationError("%s: unknown measurement %r (the experiment %s measures: %s)"
                                   % (where, name, experiment.name, ", ".join(experiment.measurements)))
        t = _field(row[1], "t_s", where, low=0.0)
        if end is not None and t > end + 1e-9:
            raise CalibrationError("%s: t_s = %g s is past the end of the experiment (%g s)" % (where, t, end))
        if (name, t) in seen:
            raise CalibrationError("%s: %s at t_s = %g s is already on line %d" % (where, name, t, seen[(name, t)]))
        seen[(name, t)] = number
        names.append(name)
        times.append(t)
        values.append(_field(row[2], "value", where))
        if with_sigma:
            sigmas.append(_field(row[3], "sigma", where, positive=True))
        numbers.append(number)
    if not names:
        raise CalibrationError("%s: a header but no data rows" % path)
    if not with_sigma:
        given = {name: experiment.measurements[name].sigma for name in set(names)}
        if any(s is not None for s in given.values()):
            missing = sorted(name for name, s in given.items() if s is None)
            if missing:
                raise CalibrationError("%s: no sigma column, and the experiment gives a sigma to some measurements but "
                                       "not to %s: give every measurement a sigma, or none (the fit then estimates the "
                                       "noise)" % (path, ", ".join(missing)))
            sigmas = [given[name] for name in names]
        else:
            sigmas = None
    return Data(names, times, values, sigmas, numbers, path)


def experiment_end(experiment):
    """The last time the experiment simulates (s), or None if only the data decides."""
    if experiment.duration_s is not None:
        return experiment.duration_s
    if experiment.journal is not None:
        return experiment.journal.duration_s
    return None


def write(path, data):
    """Writes data in the format load reads (sigma column when the data has sigmas)."""
    with open(path, "w", newline="", encoding="utf-8") as file:
        writer = csv.writer(file, lineterminator="\n")
        writer.writerow(list(REQUIRED_COLUMNS) + (["sigma"] if data.sigmas is not None else []))
        for i, name in enumerate(data.names):
            row = [name, repr(float(data.times_s[i])), repr(float(data.values[i]))]
            if data.sigmas is not None:
                row.append(repr(float(data.sigmas[i])))
            writer.writerow(row)
