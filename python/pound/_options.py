"""Python arguments as the command line's (docs/python.md, "Studies and keys").

The engine reads the module's options exactly as the program reads its command line: a study
file is ``--config PATH``, every other value ``--KEY=VALUE`` with the command's key, so that the
engine validates them with the command's rules and messages. Keyword arguments name keys with
``__`` for the dot (``contact__e`` is ``contact.e``) and ``_`` for a hyphen where the command's
key has one (``ec8_type`` is ``ec8-type``); a dict may use the keys themselves.
"""

import os
import re
from collections.abc import Mapping

import numpy as np

from ._engine import Error


def _pattern(key):
    """The regular expression of a declared key; '#' stands for a number 1, 2, ..."""
    return re.compile("^" + re.escape(key).replace(r"\#", "[1-9][0-9]*") + "$")


class Keys:
    """The declared keys of one command (from the engine), for naming keyword arguments."""

    def __init__(self, keys):
        self._patterns = [_pattern(k) for k in keys]

    def declared(self, key):
        return any(p.match(key) for p in self._patterns)

    def key_of(self, name):
        """The command's key for a keyword argument or dict key ``name``."""
        key = name.replace("__", ".")
        if self.declared(key):
            return key
        hyphen = key.replace("_", "-")
        if self.declared(hyphen):
            return hyphen
        return key  # unknown: the engine says so, listing the valid keys


def value_text(key, value):
    """A Python value as the command line writes it (floats by their shortest exact text)."""
    if isinstance(value, (bool, np.bool_)):
        return "true" if value else "false"
    if isinstance(value, (int, np.integer)):
        return str(int(value))
    if isinstance(value, (float, np.floating)):
        return repr(float(value))
    if isinstance(value, (str, os.PathLike)):
        return os.fspath(value)
    if isinstance(value, (list, tuple, np.ndarray)):
        items = np.asarray(value, dtype=object).ravel().tolist()
        if not items:
            raise Error(f"{key}: an empty list; valid: one value or a list of values")
        return ", ".join(value_text(key, v) for v in items)
    raise TypeError(f"{key}: a {type(value).__name__} is not a value of a key; valid: a number, "
                    "a string, a bool or a list of numbers")


def arguments(keys, study=None, overrides=None, refused=(), config_key="config"):
    """The command-line arguments of a study and overrides.

    ``study``: None, a path (``--config PATH``) or a dict of sections ({"building1": {"masses":
    [...]}, ...}; values outside a section are top-level keys such as ``dt``). ``overrides``:
    keyword arguments or dict keys, winning over the study's. A value None leaves a key out.
    ``refused``: keys the caller sets itself (a pound.Error names them).
    """
    args = []
    entries = {}
    if study is None:
        pass
    elif isinstance(study, (str, os.PathLike)):
        args.append(f"--{config_key}={os.fspath(study)}")
    elif isinstance(study, Mapping):
        for name, value in study.items():
            if isinstance(value, Mapping):
                for k, v in value.items():
                    entries[f"{name}.{k}"] = v
            else:
                entries[str(name)] = value
    else:
        raise TypeError(f"study: a {type(study).__name__}; valid: the path of a study file (INI) "
                        "or a dict of sections")
    for name, value in (overrides or {}).items():
        entries[keys.key_of(name)] = value
    for key, value in entries.items():
        if key in refused:
            raise Error(f"{key}: not a key here; {refused[key]}")
        if value is None:
            continue
        args.append(f"--{key}={value_text(key, value)}")
    return args
