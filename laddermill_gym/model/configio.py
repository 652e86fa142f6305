"""Strict YAML reading: every error names the file, the field and the offending value."""

from __future__ import annotations

import math
import re
from pathlib import Path
from typing import Any

import numpy as np
import yaml

from laddermill_gym.model.input_cache import note_read


class ConfigError(ValueError):
    """An invalid configuration file: the message names the file, the field and the value."""


def _find_config_dir() -> Path:
    """The shipped configs: the package data ``laddermill_gym.configs`` (a wheel or ``pip install .``); in a
    source checkout installed in editable mode that is the repository's top-level ``configs/`` itself."""
    try:  # a namespace package (no __init__.py): files() would give a MultiplexedPath, whose str() is no path
        import laddermill_gym.configs as shipped

        root = Path(next(iter(shipped.__path__)))
    except ModuleNotFoundError:  # the source tree on sys.path without any install
        root = Path(__file__).resolve().parents[2] / "configs"
    if not (root / "scenes").is_dir():
        raise FileNotFoundError(f"laddermill_gym: the shipped configs are missing (looked in {root})")
    return root


#: Folder of the shipped configuration files (scenes, wings, cables, rotors, rotorcraft, agents).
CONFIG_DIR: Path = _find_config_dir()


def config_path(kind: str, name_or_path: str | Path, base: Path | None = None) -> Path:
    """Path of a configuration file.

    ``name_or_path`` is a bare name (``"tethered_wing"``: ``CONFIG_DIR/kind/NAME.yaml``; ``"NAME.yaml"`` too when
    no such file is in the working directory), or a path: absolute, relative to ``base`` (the folder of the file that
    names it) when that file exists there, else relative to the working directory. A path that starts with
    ``package:`` names the shipped data (``package:wings/meijaard_wing.yaml``), and so does a relative path
    ``configs/KIND/FILE`` that does not exist here (``configs/agents/ppo_tethered_wing.yaml`` outside a checkout).
    ``kind`` is a folder of ``CONFIG_DIR`` (``"scenes"``, ...).
    """
    text = str(name_or_path)
    if text.startswith("package:"):
        return CONFIG_DIR / text[len("package:"):]
    p = Path(text)
    if p.suffix not in (".yaml", ".yml", ".csv") and len(p.parts) == 1 and not p.exists():
        return CONFIG_DIR / kind / f"{text}.yaml"
    if base is not None and not p.is_absolute() and (base / p).exists():
        return (base / p).resolve()
    if not p.is_absolute() and not p.exists():  # the shipped file of that name, if there is one
        shipped = (CONFIG_DIR.joinpath(*p.parts[1:]) if len(p.parts) > 2 and p.parts[0] == "configs"
                   else CONFIG_DIR / kind / p.name if len(p.parts) == 1 and base is None else None)
        if shipped is not None and shipped.is_file():
            return shipped
    return p


def shipped_names(kind: str) -> list[str]:
    """The bare names of the shipped ``CONFIG_DIR/kind/*.yaml`` files, sorted."""
    return sorted(f.stem for f in (CONFIG_DIR / kind).glob("*.yaml"))


def find_config(kind: str, name_or_path: str | Path, what: str = "") -> Path:
    """:func:`config_path` of an existing file; ConfigError naming the value (``what``: the option or field that
    gave it) and the shipped names of ``kind`` otherwise."""
    path = config_path(kind, name_or_path)
    if not path.is_file():
        named = f"{what} = {str(name_or_path)!r}: " if what else ""
        raise ConfigError(f"{named}{path}: no such file (a bare name is one of the shipped {kind}: "
                          f"{', '.join(shipped_names(kind))})")
    return path


def _show(value: Any) -> str:
    """Value as the user wrote it (numpy scalars and arrays shown as plain Python numbers)."""
    if isinstance(value, np.ndarray):
        value = value.tolist()
    if isinstance(value, (list, tuple)):
        return "[" + ", ".join(_show(v) for v in value) + "]"
    if isinstance(value, np.generic):
        value = value.item()
    return repr(value)


class Section:
    """A mapping read from a YAML file, with typed getters that validate and track unknown keys."""

    def __init__(self, data: Any, file: Path | str, path: str = ""):
        self.file = str(file)
        self.path = path
        if not isinstance(data, dict):
            shown = repr(data) if len(repr(data)) <= 80 else repr(data)[:77] + "..."  # not a whole wrong file
            raise ConfigError(f"{self.file}: {path or 'top level'} must be a mapping, got {type(data).__name__} "
                              f"{shown}")
        self.data = data
        self.used: set[str] = set()

    def _name(self, key: str) -> str:
        return f"{self.path}.{key}" if self.path else key

    def error(self, key: str, value: Any, why: str) -> ConfigError:
        return ConfigError(f"{self.file}: field '{self._name(key)}' = {_show(value)}: {why}")

    def has(self, key: str) -> bool:
        return key in self.data

    def raw(self, key: str, default: Any = ...) -> Any:
        self.used.add(key)
        if key not in self.data:
            if default is ...:
                raise ConfigError(f"{self.file}: missing field '{self._name(key)}'")
            return default
        return self.data[key]

    def number(self, key: str, default: Any = ..., *, positive=False, nonneg=False, integer=False,
               low: float | None = None, high: float | None = None, why: str = "") -> float:
        """The number at ``key`` (an int with ``integer``); ConfigError naming the file, field and value unless it
        is a finite number of magnitude at most :data:`MAX_MAGNITUDE`, > 0 (``positive``), >= 0 (``nonneg``) and
        within [``low``, ``high``] (either None: open); ``why`` says where those bounds come from."""
        v = self.raw(key, default)
        if isinstance(v, bool) or not isinstance(v, (int, float)):
            raise self.error(key, v, "must be a number" + (" (YAML reads a quoted value as text)"
                                                           if isinstance(v, str) else ""))
        if not math.isfinite(v):
            raise self.error(key, v, "must be finite")
        if abs(v) > MAX_MAGNITUDE:
            raise self.error(key, v, f"must be at most {MAX_MAGNITUDE:g} in magnitude (SI units; larger values "
                                     "overflow the simulation)")
        if positive and not v > 0:
            raise self.error(key, v, "must be > 0")
        if nonneg and v < 0:
            raise self.error(key, v, "must be >= 0")
        if (low is not None and v < low) or (high is not None and v > high):
            span = (f"between {low:g} and {high:g}" if low is not None and high is not None
                    else f"at least {low:g}" if low is not None else f"at most {high:g}")
            raise self.error(key, v, f"must be {span}" + (f" ({why})" if why else ""))
        if integer:
            if int(v) != v:
                raise self.error(key, v, "must be an integer")
            return int(v)
        return float(v)

    def flag(self, key: str, default: Any = ...) -> bool:
        v = self.raw(key, default)
        if not isinstance(v, bool):
            raise self.error(key, v, "must be true or false")
        return v

    def text(self, key: str, default: Any = ..., choices: tuple[str, ...] | None = None) -> str:
        v = self.raw(key, default)
        if v is None and default is None:
            return None
        if not isinstance(v, str):
            raise self.error(key, v, "must be a string")
        if choices and v not in choices:
            raise self.error(key, v, f"must be one of {choices}")
        return v

    def vector(self, key: str, length: int | None = None, default: Any = ...) -> np.ndarray:
        v = self.raw(key, default)
        items = v.ravel().tolist() if isinstance(v, np.ndarray) else v if isinstance(v, (list, tuple)) else []
        for x in items:  # YAML's true / "0.2" are not numbers here either (np.asarray would take them as 1.0, 0.2)
            if isinstance(x, (bool, np.bool_, str)):
                raise self.error(key, v, "must be a list of numbers" + (" (YAML reads a quoted value as text)"
                                                                        if isinstance(x, str) else ""))
        try:
            a = np.asarray(v, dtype=float)
        except (TypeError, ValueError):
            raise self.error(key, v, "must be a list of numbers") from None
        if a.ndim != 1 or (length is not None and a.size != length):
            raise self.error(key, v, f"must be a list of {length or 'some'} numbers")
        if not np.all(np.isfinite(a)):
            raise self.error(key, v, "must be finite")
        return a

    def section(self, key: str, default: Any = ...) -> Section:
        v = self.raw(key, default)
        return Section(v, self.file, self._name(key))

    def done(self) -> None:
        """Raise on keys that were never read (typos, unsupported options)."""
        extra = sorted(set(self.data) - self.used)
        if extra:
            raise ConfigError(f"{self.file}: unknown field '{self._name(extra[0])}' "
                              f"(value {self.data[extra[0]]!r}); known fields: {sorted(self.used)}")


#: The largest magnitude a config number may have [SI units]: far above any physical value of these models (the
#: stiffest cable's EA is about 1e8 N) and far below where squares and products overflow float64.
MAX_MAGNITUDE = 1e12


#: A float as YAML 1.2 writes it (the core schema): digits with a fraction, an exponent or both, ``1e6``, ``1.0e6``,
#: ``1E-3``, ``.5``, ``5.``; PyYAML's YAML 1.1 resolver reads the exponent forms without a dot or a sign (``1e6``,
#: ``1.0e6``, ``1e300``) as text.
_FLOAT_1_2 = re.compile(r"""^[-+]?(?:[0-9][0-9_]*(?:\.[0-9_]*)?|\.[0-9][0-9_]*)(?:[eE][-+]?[0-9]+)?$""")


class YAMLLoader(yaml.SafeLoader):
    """YAML's safe loader reading every float a user writes (``1e6``, ``1.0e6``, ``1e300``: YAML 1.2's core schema; a
    plain integer stays an int) and refusing a key given twice in one mapping (plain YAML keeps the last one
    silently). Every YAML file of the package is read with it (:func:`read_yaml`, :func:`load_yaml_text`)."""

    def construct_mapping(self, node, deep=False):
        seen: dict[Any, int] = {}
        for key_node, _ in node.value:
            key = self.construct_object(key_node, deep=deep)
            if key in seen:
                raise yaml.constructor.ConstructorError(
                    None, None, f"duplicated key {key!r} (first given on line {seen[key] + 1})", key_node.start_mark)
            seen[key] = key_node.start_mark.line
        return super().construct_mapping(node, deep)


# constructed by PyYAML's own float constructor (float() of the text without underscores); the integers keep
# precedence (the resolvers of a first character are tried in order and PyYAML's int comes after its float)
YAMLLoader.add_implicit_resolver("tag:yaml.org,2002:float", _FLOAT_1_2, list("-+0123456789."))
for _first, _resolvers in YAMLLoader.yaml_implicit_resolvers.items():
    _ints = [r for r in _resolvers if r[0] == "tag:yaml.org,2002:int"]
    _resolvers[:] = _ints + [r for r in _resolvers if r[0] != "tag:yaml.org,2002:int"]


def load_yaml_text(text: str, where: str) -> Any:
    """The YAML document ``text`` read with :class:`YAMLLoader`; ConfigError naming ``where`` (a file, an option)
    for invalid YAML or a key given twice."""
    try:
        return yaml.load(text, Loader=YAMLLoader)  # noqa: S506 (a SafeLoader subclass)
    except yaml.YAMLError as err:
        raise ConfigError(f"{where}: not valid YAML: {err}") from None


def read_yaml(path: Path | str) -> Section:
    """The YAML file as a strict :class:`Section`; ConfigError for a missing file, invalid YAML or a key given
    twice in one mapping (naming the line)."""
    path = Path(path)
    if not path.is_file():
        raise ConfigError(f"{path}: no such file")
    note_read(path)  # an in-process cache keyed on a file name checks these bytes on a hit (model/input_cache.py)
    try:
        text = path.read_text(encoding="utf-8")
    except UnicodeDecodeError as err:  # an image or another binary file given for a config
        raise ConfigError(f"{path}: not a UTF-8 text YAML file (byte {err.start}: {err.reason})") from None
    except OSError as err:
        raise ConfigError(f"{path}: cannot be read ({err.strerror or err})") from None
    data = load_yaml_text(text, str(path))
    return Section(data if data is not None else {}, path)
