"""A scenario file as the scripts read it: its YAML with the file its `base` key names read first
(a path relative to the file's folder, followed the same way), each key of a file overriding its
base's, as the C++ loader does (src/core/scenario.cpp). Values are as YAML gives them; the C++
loader is the one that checks them (ranges, required keys)."""
import os

import yaml

MAX_BASE_DEPTH = 8  # as kMaxBaseDepth in scenario.cpp


def load(path, _chain=()):
    """The scenario at `path` as {section: {key: value}}, its bases merged in (a key of the file
    overrides its base's; "description" too, where the file has one). Raises ValueError for a
    file that is not a map, an empty or non-text base, a cycle or a chain too deep, and OSError or
    yaml.YAMLError as reading does."""
    real = os.path.realpath(path)
    if real in _chain:
        raise ValueError(f"{path}: base: the files name each other in a cycle")
    if len(_chain) >= MAX_BASE_DEPTH:
        raise ValueError(f"{path}: base: more than {MAX_BASE_DEPTH} files deep")
    with open(path) as f:
        text = yaml.safe_load(f)
    if text is None:
        text = {}
    if not isinstance(text, dict):
        raise ValueError(f"{path}: expected a map of sections")
    merged = {}
    if "base" in text:
        base = text["base"]
        if not isinstance(base, str) or not base:
            raise ValueError(f"{path}: base: {base!r}; allowed: the path of a scenario file")
        merged = load(base if os.path.isabs(base) else os.path.join(os.path.dirname(path), base), _chain + (real,))
    for section, keys in text.items():
        if isinstance(keys, dict):
            merged.setdefault(section, {}).update(keys)
        else:
            merged[section] = keys
    return merged
