"""Cases: a TOML case file (or a dict, or text) with ``--set`` overrides, read by the engine."""

import copy as _copy
import os
import tomllib

from . import _core, _toml


class Case:
    """A sloshsph case: its TOML text, where it came from, and the overrides applied to it.

    The engine reads it exactly as ``sloshsph run CASE --set KEY=VALUE ...`` does: every key is
    checked, defaults are filled in, and a bad key, type or value raises ``CaseError`` with the
    program's message (docs/case-format.md lists every key).

    Make one with ``Case.from_file(path)``, ``Case.from_dict(d)``, ``Case.from_text(text)`` or
    ``Case.default()``; override keys with ``case.set("time.end", 2.0)`` or
    ``case["time.end"] = 2.0``. Relative paths in a case file (record files) are relative to the
    file's folder; in a case made from a dict or text, to the current directory.

    Example::

        case = sloshsph.Case.from_file("cases/liu_lin_2008.toml")
        case.set("time.end", 3.0).set("excitation.beta", 1.05)
        case.validate()
        print(case["excitation.amplitude"])
    """

    def __init__(self, text, source="<text>", name="case", overrides=()):
        self._text = text
        self._source = source
        self.name = name
        self._overrides = list(overrides)

    # -- making cases ------------------------------------------------------------------------
    @classmethod
    def from_file(cls, path):
        """The case file at ``path`` (named after the file's stem, as ``sloshsph run`` names it)."""
        path = os.fspath(path)
        data = _core.read_case_file_text(path)
        try:
            text = data.decode("utf-8")
        except UnicodeDecodeError:
            text = data  # as bytes: the engine reports where the text is not UTF-8, as the program does
        return cls(text, path, os.path.splitext(os.path.basename(path))[0])

    @classmethod
    def from_dict(cls, tables, name="case"):
        """A case from a dict of tables, as the TOML file would hold them::

        Case.from_dict({"tank": {"shape": "rectangle", "length": 0.6, "height": 0.4},
                        "fill": {"depth": 0.12}, "particles": {"dp": 0.01},
                        "time": {"end": 2.0, "dt": 1e-3},
                        "probes": {"gauge": [{"name": "left", "x": 0.01}]}})
        """
        return cls(_toml.dumps(tables), f"<dict {name}>", name)

    @classmethod
    def from_text(cls, text, name="case"):
        """A case from TOML text."""
        return cls(text, f"<text {name}>", name)

    @classmethod
    def default(cls):
        """The built-in default case of ``sloshsph run`` without a case file."""
        return cls(_core.default_case_text(), "<built-in default case>", "default")

    def copy(self):
        """An independent copy (its overrides can change without changing this one)."""
        return _copy.deepcopy(self)

    # -- overrides ---------------------------------------------------------------------------
    @property
    def overrides(self):
        """The ``KEY=VALUE`` texts applied, in order (as ``--set`` options)."""
        return list(self._overrides)

    @property
    def source(self):
        """The file the case came from, or ``<dict NAME>`` / ``<text NAME>``."""
        return self._source

    def set(self, key, value):
        """Overrides one key, as ``--set KEY=VALUE`` does; returns the case (calls chain).

        ``value`` is a Python value (number, bool, str, list, dict), written as its TOML literal.
        A numeric segment of ``key`` indexes an array of tables: ``"probes.gauge.0.x"``. The
        override's syntax is checked now; whether the key exists, when the case is read
        (``validate``, ``run``).
        """
        return self.set_text(f"{key}={_toml.value(value)}")

    def set_text(self, assignment):
        """Overrides with a ``KEY=VALUE`` text exactly as given on the command line (VALUE is TOML,
        a bare word a string)."""
        _core.case_text_with_overrides(self._text, self._source, self._overrides + [assignment])
        self._overrides.append(assignment)
        return self

    def __setitem__(self, key, value):
        self.set(key, value)

    def __getitem__(self, key):
        """The value of a dotted key with the overrides applied (``case["probes.gauge.0.x"]``);
        ``resolved()[key]`` gives defaults too. KeyError if the case does not set it."""
        node = self.to_dict()
        for part in key.split("."):
            if isinstance(node, list) and part.isdigit() and int(part) < len(node):
                node = node[int(part)]
            elif isinstance(node, dict) and part in node:
                node = node[part]
            else:
                raise KeyError(key)
        return node

    # -- reading -----------------------------------------------------------------------------
    def validate(self):
        """Reads and resolves the case as a run would; raises ``CaseError`` naming the key (the
        program's exit 2). Returns the case. (A few checks need the particles, e.g. the time
        step's stability bound: ``run`` makes those before it writes anything.)"""
        _core.check_case(self._text, self._source, self.name, self._overrides)
        return self

    def resolved(self):
        """The case with every default filled in (what a run keeps as case.toml), as a new Case."""
        name, text = _core.check_case(self._text, self._source, self.name, self._overrides)
        return Case(text, f"<resolved {name}>", name)

    def to_toml(self, resolved=False):
        """The case as TOML text: with the overrides applied, or (``resolved=True``) every key."""
        if resolved:
            return _core.check_case(self._text, self._source, self.name, self._overrides)[1]
        if not self._overrides:
            return self._text
        return _core.case_text_with_overrides(self._text, self._source, self._overrides)

    def to_dict(self, resolved=False):
        """The case as a dict of tables (see ``to_toml``)."""
        return tomllib.loads(self.to_toml(resolved))

    def write(self, path, resolved=False):
        """Writes the case file (see ``to_toml``); ``sloshsph run PATH`` then runs the same case."""
        with open(os.fspath(path), "w", encoding="utf-8") as f:
            f.write(self.to_toml(resolved))

    def __repr__(self):
        extra = f", {len(self._overrides)} overrides" if self._overrides else ""
        return f"<sloshsph.Case {self.name!r} from {self._source}{extra}>"


def as_case(case):
    """A Case from a Case, a path or a dict."""
    if isinstance(case, Case):
        return case
    if isinstance(case, dict):
        return Case.from_dict(case)
    if isinstance(case, (str, os.PathLike)):
        return Case.from_file(case)
    raise TypeError(f"a case is a sloshsph.Case, a case file's path or a dict, not {type(case).__name__}")
