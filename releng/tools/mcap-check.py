#!/usr/bin/env python3
"""Independent check of spy logs with the official `mcap` Python package (PyPI: mcap).

For each file: the summary (statistics, channels, chunk indexes) is read through the index, every
chunk is decompressed and CRC-checked, message counts per channel must equal the statistics, and each
wire channel must be a gap-free byte stream: every message's stream offset equals the previous
offset plus the previous message's wire bytes. JSON channels other than /events (decoded messages an
export adds for Foxglove) must hold JSON that fits their channel's JSON Schema. Exit status 1 on any
failure, with the file and why.

usage: mcap-check.py LOG.mcap [...]
"""
import json
import struct
import sys
from collections import Counter

from mcap.reader import make_reader

WIRE_PREFIX = struct.Struct("<QBH")  # stream offset, kind, reason length
JSON_TYPES = {"integer": (int,), "number": (int, float), "null": (type(None),), "string": (str,), "boolean": (bool,),
              "array": (list,), "object": (dict,)}


def fits(value, schema, where):
    """Checks a decoded JSON value against the parts of JSON Schema the export writes."""
    if "anyOf" in schema:
        problems = []
        for alternative in schema["anyOf"]:
            try:
                fits(value, alternative, where)
                return
            except ValueError as e:
                problems.append(str(e))
        raise ValueError(f"{where}: fits none of anyOf ({'; '.join(problems)})")
    kind = schema.get("type")
    if kind is None:
        return
    if not isinstance(value, JSON_TYPES[kind]) or (kind in ("integer", "number") and isinstance(value, bool)):
        raise ValueError(f"{where}: {value!r} is not {kind}")
    if kind == "object":
        for name in schema.get("required", []):
            if name not in value:
                raise ValueError(f"{where}: no {name}")
        for name, sub in schema.get("properties", {}).items():
            if name in value:
                fits(value[name], sub, f"{where}.{name}")
    elif kind == "array" and "items" in schema:
        for i, item in enumerate(value):
            fits(item, schema["items"], f"{where}[{i}]")


def check(path):
    with open(path, "rb") as f:
        reader = make_reader(f, validate_crcs=True)
        header = reader.get_header()
        if header.profile != "x-stagecraft-spy":
            raise ValueError(f"profile is {header.profile!r}, not x-stagecraft-spy")
        summary = reader.get_summary()
        if summary is None or summary.statistics is None:
            raise ValueError("no summary section / statistics (was the log closed?)")
        stats = summary.statistics
        counts = Counter()
        next_offset = {}
        wire_bytes = 0
        events = Counter()
        json_messages = 0
        for schema, channel, message in reader.iter_messages(log_time_order=False):
            counts[channel.id] += 1
            if channel.message_encoding == "x-player-xdr":
                offset, kind, reason_len = WIRE_PREFIX.unpack_from(message.data)
                payload = len(message.data) - WIRE_PREFIX.size - reason_len
                if kind not in (1, 2, 3):
                    raise ValueError(f"{channel.topic}: unknown wire kind {kind}")
                expected = next_offset.get(channel.id, 0)
                if offset != expected:
                    raise ValueError(f"{channel.topic}: message at offset {offset}, expected {expected} (gap or overlap)")
                next_offset[channel.id] = offset + payload
                wire_bytes += payload
            elif channel.message_encoding == "json" and channel.topic == "/events":
                events[json.loads(message.data)["event"]] += 1
            elif channel.message_encoding == "json":
                decoded = json.loads(message.data)
                if schema is not None and schema.encoding == "jsonschema":
                    fits(decoded, json.loads(schema.data), channel.topic)
                json_messages += 1
            else:
                raise ValueError(f"{channel.topic}: unexpected encoding {channel.message_encoding}")
        total = sum(counts.values())
        if total != stats.message_count:
            raise ValueError(f"read {total} messages, statistics say {stats.message_count}")
        for cid, n in counts.items():
            if stats.channel_message_counts.get(cid) != n:
                raise ValueError(f"channel {cid}: read {n}, statistics say {stats.channel_message_counts.get(cid)}")
        if events["opened"] != events["closed"]:
            raise ValueError(f"{events['opened']} connections opened but {events['closed']} closed")
        compression = sorted({ci.compression for ci in summary.chunk_indexes})
        print(f"{path}: ok — {total} messages, {len(summary.channels)} channels, {len(summary.chunk_indexes)} chunks "
              f"({'/'.join(compression)}), {wire_bytes} wire bytes gap-free, {events['opened']} connections"
              + (f", {json_messages} decoded JSON messages" if json_messages else ""))


def main(paths):
    if not paths:
        print(__doc__.strip().splitlines()[-1], file=sys.stderr)
        return 2
    failed = 0
    for p in paths:
        try:
            check(p)
        except Exception as e:  # report every file, then fail
            print(f"{p}: FAILED — {e}", file=sys.stderr)
            failed += 1
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
