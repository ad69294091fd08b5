#!/usr/bin/python3
"""fpmshell with keys added to (or replaced in) the model file, for option studies: `--set`
only overrides keys the file already has. Used in place of the binary by the validation
scripts (`run.py --fpmshell tools/with_keys.py`).
  FPM_BIN   the fpmshell binary
  FPM_KEYS  'path=value;path=value', a path of YAML keys with list items numbered from 0 or *
            for every item, e.g. 'control.rotary_inertia=abaqus;sections.*.inplane_points=3'
The model is written to a hidden file beside the original (mesh paths stay valid) and removed
after the run."""
import os
import subprocess
import sys
import tempfile

import yaml


def put(node, path, value):
    head, rest = path[0], path[1:]
    if isinstance(node, list):
        items = node if head == "*" else [node[int(head)]]
        for item in items:
            if rest:
                put(item, rest, value)
            else:
                raise SystemExit("with_keys.py: a list item cannot be replaced: " + ".".join(path))
        return
    if not rest:
        node[head] = value
    else:
        put(node.setdefault(head, {}), rest, value)


def main():
    binary = os.environ["FPM_BIN"]
    keys = [kv for kv in os.environ.get("FPM_KEYS", "").split(";") if kv]
    args = sys.argv[1:]
    if not keys or len(args) < 2 or args[0] not in ("run", "check"):
        os.execv(binary, [binary] + args)
    model = os.path.abspath(args[1])
    with open(model) as f:
        doc = yaml.safe_load(f)
    for kv in keys:
        path, value = kv.split("=", 1)
        put(doc, path.split("."), yaml.safe_load(value))
    fd, tmp = tempfile.mkstemp(prefix=".with_keys_", suffix=".yaml", dir=os.path.dirname(model))
    with os.fdopen(fd, "w") as f:
        yaml.safe_dump(doc, f, sort_keys=False)
    try:
        return subprocess.call([binary, args[0], tmp] + args[2:])
    finally:
        os.unlink(tmp)


if __name__ == "__main__":
    sys.exit(main())
