#!/usr/bin/env python3
"""PyYAML oracle for gc_yaml's tests.

Values are written as tagged JSON so that ints, floats, bools and strings stay
distinct: ["null"], ["bool", b], ["int", "<decimal>"], ["float", "<repr>"],
["str", s], ["seq", [...]], ["map", [[k, v], ...]], ["other", "<type>"].
A load result is {"ok": tagged} or {"err": "<Exception>: <message>"}; a mapping
with duplicate keys (which PyYAML silently merges but gc_yaml rejects) is
reported as {"err": "duplicate: ..."}.

Usage (run with /work/refenv/bin/python):
  pyyaml_oracle.py load   < docs.json     JSON list of YAML texts -> list of load results
  pyyaml_oracle.py dump   < values.json   JSON list of tagged values -> list of dump texts
  pyyaml_oracle.py reference <root> <out.json>   load every YAML file under <root>
  pyyaml_oracle.py tables <out_dir>      regenerate tests/data/{scalars,emit}.json
"""
import json
import math
import os
import random
import sys

import yaml


class Pairs:
    """A mapping kept as a list of pairs (unhashable, like dict)."""
    __hash__ = None

    def __init__(self, pairs):
        self.pairs = pairs


class DuplicateKey(Exception):
    pass


class PairLoader(yaml.SafeLoader):
    pass


def _construct_map(loader, node):
    # Same as SafeConstructor.construct_mapping, but keeps pairs and flags duplicates.
    loader.flatten_mapping(node)
    pairs, seen = [], {}
    for key_node, value_node in node.value:
        key = loader.construct_object(key_node, deep=True)
        try:
            hash(key)
        except TypeError:
            raise yaml.constructor.ConstructorError(
                "while constructing a mapping", node.start_mark,
                "found unhashable key", key_node.start_mark)
        if key in seen:
            raise DuplicateKey("duplicate key %r at line %d" % (key, key_node.start_mark.line + 1))
        seen[key] = True
        pairs.append((key, loader.construct_object(value_node, deep=True)))
    return Pairs(pairs)


PairLoader.add_constructor('tag:yaml.org,2002:map', _construct_map)


def tag(v):
    if v is None:
        return ["null"]
    if isinstance(v, bool):
        return ["bool", v]
    if isinstance(v, int):
        return ["int", str(v)]
    if isinstance(v, float):
        return ["float", repr(v)]
    if isinstance(v, str):
        return ["str", v]
    if isinstance(v, list):
        return ["seq", [tag(x) for x in v]]
    if isinstance(v, Pairs):
        return ["map", [[tag(k), tag(x)] for k, x in v.pairs]]
    if isinstance(v, dict):
        return ["map", [[tag(k), tag(x)] for k, x in v.items()]]
    return ["other", type(v).__name__]


def untag(t):
    kind = t[0]
    if kind == "null":
        return None
    if kind in ("bool", "str"):
        return t[1]
    if kind == "int":
        return int(t[1])
    if kind == "float":
        return float(t[1])
    if kind == "seq":
        return [untag(x) for x in t[1]]
    if kind == "map":
        return {untag(k): untag(v) for k, v in t[1]}
    raise ValueError(kind)


def load_one(text):
    try:
        # Compare with safe_load too: the pair loader must agree with it.
        v = yaml.load(text, Loader=PairLoader)
        return {"ok": tag(v)}
    except DuplicateKey as e:
        return {"err": "duplicate: %s" % e}
    except RecursionError:
        return {"err": "RecursionError"}
    except Exception as e:  # noqa: BLE001 - any failure is an expected error
        return {"err": "%s: %s" % (type(e).__name__, str(e).replace("\n", " | "))}


def dump_one(v):
    return yaml.dump(v, default_flow_style=False, sort_keys=False)


def reference(root, out):
    result = {}
    for dirpath, _, files in os.walk(root):
        for f in sorted(files):
            if f.endswith((".yaml", ".yml")):
                path = os.path.join(dirpath, f)
                with open(path, encoding="utf-8", newline="") as fh:
                    text = fh.read()
                result[os.path.relpath(path, root)] = load_one(text)
    with open(out, "w") as fh:
        fh.write("{\n" + ",\n".join("%s: %s" % (json.dumps(k), json.dumps(result[k]))
                                     for k in sorted(result)) + "\n}\n")
    print("wrote %d files to %s" % (len(result), out))


def tricky_scalars():
    """Scalars exercising every branch of the YAML 1.1 resolver."""
    out = set()
    words = ["null", "Null", "NULL", "nULL", "~", "~~", "true", "True", "TRUE", "tRUE", "false", "False",
             "FALSE", "yes", "Yes", "YES", "yEs", "no", "No", "NO", "nO", "on", "On", "ON", "oN", "off",
             "Off", "OFF", "y", "Y", "n", "N", "t", "f", "nan", "NaN", ".nan", ".NaN", ".NAN", ".Nan",
             "inf", ".inf", ".Inf", ".INF", ".iNF", "-.inf", "+.inf", "-.Inf", "+.INF", "-.nan", "+.nan",
             "=", "==", "<<", "<", "<<<", "0o17", "0O17", "0b", "0x", "0b_", "0x_", "0b102", "0xG",
             "0X1F", "0B101", "1e3", "1E3", "1e+3", "1.0e3", "1.0e+3", "1.0E-3", "1.e+3", ".5e+3", ".5e3",
             "-.5", "+.5", ".5", "5.", "-5.", "+5.", "._5", "._", ".", "..", "-", "+", "-0", "+0", "0",
             "00", "08", "09", "010", "0_", "0__", "_0", "_1", "1_", "1__", "1_000", "1_000.5", "1__0.0_",
             "1,000", "1.000.000", "0.0", "-0.0", "+0.0", "0.", "00.", "00.5", "1:30", "1:30.5", "1:60",
             "1:5:9", "190:20:30", "190:20:30.15", "-1:30", "+1:30", "1:3a", "1:", ":30", "0:30", "01:30",
             "1_0:30", "1:30:", "1::30", "1:30.5.5", "2001-12-14", "2001-12-14t21:59:43.10-05:00",
             "2001-12-14 21:59:43.10 -5", "2001-12-15 2:59:43.10", "2002-12-14", "2001-1-1",
             "2001-01-01 1:02:03", "2001-01-01 1:02:03Z", "2001-01-01 1:02:03 Z", "2001-01-01T1:02:03+01:00",
             "2001-01-01 1:02:03.", "2001-01-01  1:02:03", "2001-01-01 1:02", "20011-01-01", "2001-01-011",
             "2001-13-45", "9223372036854775807", "9223372036854775808", "-9223372036854775808",
             "-9223372036854775809", "0x7FFFFFFFFFFFFFFF", "0x8000000000000000", "-0x8000000000000000",
             "0777", "-0777", "+0777", "0b1111", "-0b1_1", "0x_F", "1e400", "1.0e+400", "-1.0e+400",
             "1.0e-400", "123456789012345678901234567890.5", "0.1", "0.30000000000000004", "1.7976931348623157e+308",
             "FittedShirt", "Sun", "a b", "a  b", "a:b", "a# b", "a #b", "a,b", "[a]", "{a}", "a]", "a}",
             "'a'", "\"a\"", "-a", "--a", "---", "...", "....", "?a", ":a", "!a", "&a", "*a", "%a", "@a",
             "`a", "|a", ">a", "#a", "a'", "a\"", "é", "ü-ber", "日本", "\u00a0", "a\tb", "1 2", "1.0 ",
             " 1.0", "true false", "null null"]
    out.update(words)
    rnd = random.Random(1234)
    alphabet = "0123456789_.:+-eExXbBoO"
    for _ in range(2500):
        n = rnd.randint(1, 8)
        out.add("".join(rnd.choice(alphabet) for _ in range(n)))
    return sorted(out)


def random_float(rnd):
    r = rnd.random()
    if r < 0.3:
        return round(rnd.uniform(-100, 100), rnd.randint(0, 6))
    if r < 0.6:
        return rnd.uniform(-1, 1) * 10 ** rnd.randint(-30, 30)
    if r < 0.8:
        import struct
        return struct.unpack("<d", struct.pack("<Q", rnd.getrandbits(64)))[0]
    return rnd.choice([0.0, -0.0, 1.0, 1e16, 1e15, 1e-4, 1e-5, 123456789012345.6, 5e-324, 1e308,
                       float("inf"), float("-inf"), 0.1, 2.5, 100.0])


def random_text(rnd):
    pieces = ["a", "b", "word", " ", "  ", ":", ": ", " #", "#", "-", "- ", "'", "\"", "\\", "\n", "\n\n",
              "\t", "é", "日", "\u2028", "\x85", "\x00", "\x07", "\ufeff", "\xa0", "1", "1.0", "true", "null",
              "[", "]", "{", "}", ",", "?", "!", "&", "*", "|", ">", "%", "@", "`", "---", "...", "~", "="]
    r = rnd.random()
    if r < 0.15:
        # Long text with spaces: exercises line folding at 80 columns.
        return " ".join(rnd.choice(["alpha", "beta", "gamma", "x" * rnd.randint(1, 30), "d"])
                        for _ in range(rnd.randint(10, 40)))
    if r < 0.25:
        return "".join(rnd.choice(["ab", " ", "\n", "cd ", " ef", "\\", "\"", "'", "é"]) for _ in range(rnd.randint(20, 60)))
    return "".join(rnd.choice(pieces) for _ in range(rnd.randint(0, 6)))


def random_value(rnd, depth=0):
    r = rnd.random()
    if depth < 4 and r < 0.25:
        return [random_value(rnd, depth + 1) for _ in range(rnd.randint(0, 4))]
    if depth < 4 and r < 0.5:
        d = {}
        for _ in range(rnd.randint(0, 4)):
            k = random_key(rnd)
            if k not in d:
                d[k] = random_value(rnd, depth + 1)
        return d
    r = rnd.random()
    if r < 0.1:
        return None
    if r < 0.2:
        return rnd.random() < 0.5
    if r < 0.35:
        return rnd.choice([0, 1, -1, 7, 2 ** 63 - 1, -2 ** 63, rnd.randint(-10 ** 6, 10 ** 6)])
    if r < 0.55:
        return random_float(rnd)
    return random_text(rnd)


def random_key(rnd):
    r = rnd.random()
    if r < 0.6:
        return rnd.choice(["v", "range", "type", "default_prob", "flare-skirt", "a b", "1", "null", "yes", ""]) \
            + ("" if rnd.random() < 0.7 else random_text(rnd))
    if r < 0.7:
        return rnd.choice([None, True, False, 0, 1, 2, 1.5, -3])
    return random_text(rnd)


def write_lines(path, entries):
    """A JSON list with one entry per line (readable diffs)."""
    with open(path, "w") as fh:
        fh.write("[\n" + ",\n".join(json.dumps(e) for e in entries) + "\n]\n")


def tables(out_dir):
    scalars = []
    for s in tricky_scalars():
        scalars.append({"s": s, "load": load_one("x: " + s), "dump": dump_one({"x": s})})
    write_lines(os.path.join(out_dir, "scalars.json"), scalars)
    rnd = random.Random(99)
    emit = []
    for i in range(1500):
        v = random_value(rnd) if i >= 300 else random_float(rnd)
        text = dump_one(v)
        emit.append({"value": tag(v), "dump": text, "load": load_one(text)})
    write_lines(os.path.join(out_dir, "emit.json"), emit)
    print("wrote %d scalars, %d emitter cases" % (len(scalars), len(emit)))


def main():
    mode = sys.argv[1]
    if mode == "load":
        docs = json.load(sys.stdin)
        json.dump([load_one(d) for d in docs], sys.stdout)
    elif mode == "dump":
        values = json.load(sys.stdin)
        json.dump([dump_one(untag(v)) for v in values], sys.stdout)
    elif mode == "reference":
        reference(sys.argv[2], sys.argv[3])
    elif mode == "tables":
        tables(sys.argv[2])
    else:
        sys.exit("unknown mode %r" % mode)


if __name__ == "__main__":
    main()
