"""A scenario file as the scripts read it: its YAML with the file its `base` key names read first
(a path relative to the file's folder, followed the same way), each key of a file overriding its
base's, as the C++ loader does (src/core/scenario.cpp). Values are as YAML gives them; the C++
loader is the one that checks them."""
import os

import yaml

MAX_BASE_DEPTH = 8  # as kMaxBaseDepth in scenario.cpp


def load(path, _depth=0):
    """The scenario at `path` as {section: {key: value}}, its bases merged in; "description" and
    "base" are the file's own. Raises ValueError for a chain too deep, OSError / yaml.YAMLError as
    reading does."""
    if _depth >= MAX_BASE_DEPTH:
        raise ValueError(f"{path}: base: more than {MAX_BASE_DEPTH} files deep")
    with open(path) as f:
        text = yaml.safe_load(f) or {}
    merged = {}
    base = text.get("base")
    if base:
        merged = load(base if os.path.isabs(base) else os.path.join(os.path.dirname(path), base), _depth + 1)
    for section, keys in text.items():
        if isinstance(keys, dict):
            merged.setdefault(section, {}).update(keys)
        else:
            merged[section] = keys
    return merged
