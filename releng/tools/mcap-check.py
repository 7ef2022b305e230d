#!/usr/bin/env python3
"""Independent check of MCAP files (spy logs, exports) with MCAP's own Python library (PyPI: mcap) and
protobuf (PyPI: protobuf), standing in for the official `mcap` CLI where it cannot be had (CI).

For each file, what `mcap doctor --strict-message-order` checks and Stagecraft relies on, as errors
(the doctor's warnings too): every CRC (chunks, data end, summary); log times never going back in file
order; each chunk's start/end times those of its messages; schemas with an encoding (never empty), no
schema id 0; every message's channel and every channel's schema defined before use, once in the data
section, the same in the summary; the statistics (message counts per channel, times, chunk count) and
the chunk index matching what the file holds; a header library and no profile but a well-known one.

Then what `mcap cat --json` does: every message must become JSON. A channel without a schema must be
`json`-encoded; a `jsonschema` schema's messages must be JSON; a `protobuf` schema's messages must parse
with the message its FileDescriptorSet names (printed as JSON as cat does); any other schema encoding
fails, as cat fails on it (this check has no ros1msg decoder: no Stagecraft file uses it).

For a spy log (session metadata `stagecraft.session`): each wire channel must be a gap-free byte stream
(every message's stream offset is the previous offset plus the previous message's bytes), connections
opened equal connections closed, and decoded JSON channels (an export's) must fit their JSON Schema.
Exit status 1 on any failure, with the file and why.

`--self-test` first makes files that the official tool rejects (a message out of order, a schema
with an empty encoding, a schema-less non-JSON channel, a damaged chunk) with the Python library's
writer and fails unless this check rejects each of them too, and accepts a good one.

usage: mcap-check.py [--self-test] FILE.mcap [...]
"""
import json
import struct
import sys
import zlib
from collections import Counter

from google.protobuf import descriptor_pb2, descriptor_pool, json_format, message_factory
from mcap.records import Channel, Chunk, ChunkIndex, DataEnd, Footer, Header, Message, MessageIndex, Metadata, Schema, \
    Statistics
from mcap.stream_reader import StreamReader, breakup_chunk

MAGIC = b"\x89MCAP0\r\n"
WELL_KNOWN_PROFILES = ("", "ros1", "ros2")
JSON_TYPES = {"integer": (int,), "number": (int, float), "null": (type(None),), "string": (str,), "boolean": (bool,),
              "array": (list,), "object": (dict,)}
OLD_WIRE_PREFIX = struct.Struct("<QBH")  # logs before version 2: stream offset, kind, reason length


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


class ProtobufDecoders:
    """What cat does for a protobuf schema: the FileDescriptorSet, the message it names, parse, to JSON."""

    def __init__(self):
        self.by_schema = {}

    def decode(self, schema, data):
        cls = self.by_schema.get(schema.id)
        if cls is None:
            files = descriptor_pb2.FileDescriptorSet.FromString(schema.data)
            pool = descriptor_pool.DescriptorPool()
            for f in files.file:
                pool.Add(f)
            cls = message_factory.GetMessageClass(pool.FindMessageTypeByName(schema.name))
            self.by_schema[schema.id] = cls
        m = cls.FromString(data)
        return m, json_format.MessageToJson(m)


def check_summary_crc(data, footer_at, footer):
    if footer.summary_start == 0 or footer.summary_crc == 0:
        return
    crc = zlib.crc32(data[footer.summary_start:footer_at + 1 + 8 + 8 + 8])
    if crc != footer.summary_crc:
        raise ValueError(f"summary CRC mismatch ({crc:08x} != {footer.summary_crc:08x})")


def check(path):
    with open(path, "rb") as f:
        data = f.read()
    if not data.startswith(MAGIC) or not data.endswith(MAGIC):
        raise ValueError("no MCAP magic at the start and the end (was the file closed?)")
    problems = []
    header = None
    schemas, channels = {}, {}  # data section
    summary_schemas, summary_channels = {}, {}
    statistics, footer, data_end = None, None, None
    metadata = {}
    chunk_indexes = []
    chunks = []  # (offset, length, start, end, message count)
    counts = Counter()
    min_time, max_time, last_time = None, None, None
    in_summary = False
    protobuf = ProtobufDecoders()
    spy = {"next_offset": {}, "wire_bytes": 0, "events": Counter(), "json": 0}

    def message(msg, where):
        nonlocal min_time, max_time, last_time
        channel = channels.get(msg.channel_id)
        if channel is None:
            raise ValueError(f"{where}: message on channel {msg.channel_id} before its Channel record")
        if last_time is not None and msg.log_time < last_time:
            raise ValueError(f"{where}: log_time {msg.log_time} on {channel.topic} is before the previous message's "
                             f"{last_time} (strict message order)")
        last_time = msg.log_time
        min_time = msg.log_time if min_time is None else min(min_time, msg.log_time)
        max_time = msg.log_time if max_time is None else max(max_time, msg.log_time)
        counts[msg.channel_id] += 1
        cat_json(channel, schemas.get(channel.schema_id), msg)

    def cat_json(channel, schema, msg):
        where = f"{channel.topic} message {msg.sequence}"
        if schema is None or schema.encoding == "":
            if channel.message_encoding != "json":
                raise ValueError(f"{where}: mcap cat --json refuses schema-less channels not encoded as json "
                                 f"(found {channel.message_encoding!r})")
            decoded = json.loads(msg.data)
        elif schema.encoding == "jsonschema":
            decoded = json.loads(msg.data)
        elif schema.encoding == "protobuf":
            if channel.message_encoding != "protobuf":
                raise ValueError(f"{where}: protobuf schema on a {channel.message_encoding!r} channel")
            decoded, _ = protobuf.decode(schema, msg.data)
        else:
            raise ValueError(f"{where}: mcap cat --json supports ros1msg, protobuf and jsonschema schemas, "
                             f"not {schema.encoding!r} (this check: protobuf and jsonschema)")
        spy_message(channel, schema, msg, decoded, where)

    def spy_message(channel, schema, msg, decoded, where):
        if schema is not None and schema.name == "stagecraft.spy.WireMessage":
            offset, payload = decoded.offset, len(decoded.wire)
            if decoded.kind not in (1, 2, 3):
                raise ValueError(f"{where}: unknown wire kind {decoded.kind}")
        elif channel.message_encoding == "x-player-xdr":
            offset, kind, reason_len = OLD_WIRE_PREFIX.unpack_from(msg.data)
            payload = len(msg.data) - OLD_WIRE_PREFIX.size - reason_len
        else:
            if channel.topic == "/events" and channel.message_encoding == "json":
                spy["events"][decoded["event"]] += 1
            elif channel.message_encoding == "json":
                if schema is not None and schema.encoding == "jsonschema":
                    fits(decoded, json.loads(schema.data), channel.topic)
                spy["json"] += 1
            return
        expected = spy["next_offset"].get(channel.id, 0)
        if offset != expected:
            raise ValueError(f"{channel.topic}: message at stream offset {offset}, expected {expected} (gap or overlap)")
        spy["next_offset"][channel.id] = offset + payload
        spy["wire_bytes"] += payload

    def schema_record(s):
        if s.id == 0:
            raise ValueError("Schema id 0 is reserved")
        if s.encoding == "":
            raise ValueError(f"schema {s.id} {s.name!r} has an empty encoding (doctor: "
                             + ("warning" if not s.data else "error") + ")")
        if in_summary:
            if schemas.get(s.id) != s:
                raise ValueError(f"summary schema {s.id} is not the data section's")
            summary_schemas[s.id] = s
        else:
            if s.id in schemas:
                raise ValueError(f"schema {s.id} recorded twice in the data section (doctor: warning)")
            schemas[s.id] = s

    def channel_record(c):
        if c.schema_id != 0 and c.schema_id not in schemas:
            raise ValueError(f"channel {c.id} {c.topic!r} names schema {c.schema_id}, not defined before it")
        if in_summary:
            if channels.get(c.id) != c:
                raise ValueError(f"summary channel {c.id} is not the data section's")
            summary_channels[c.id] = c
        else:
            if c.id in channels:
                raise ValueError(f"channel {c.id} recorded twice in the data section (doctor: warning)")
            channels[c.id] = c

    offset = len(MAGIC)
    for record in StreamReader(path, emit_chunks=True, validate_crcs=True).records:
        if isinstance(record, Header):
            header = record
        elif isinstance(record, Schema):
            schema_record(record)
        elif isinstance(record, Channel):
            channel_record(record)
        elif isinstance(record, Message):
            raise ValueError("a message outside a chunk (Stagecraft writes none)")
        elif isinstance(record, Chunk):
            times = []
            for r in breakup_chunk(record, validate_crc=True):
                if isinstance(r, Schema):
                    schema_record(r)
                elif isinstance(r, Channel):
                    channel_record(r)
                elif isinstance(r, Message):
                    message(r, f"chunk {len(chunks)}")
                    times.append(r.log_time)
            if times and (min(times) != record.message_start_time or max(times) != record.message_end_time):
                raise ValueError(f"chunk {len(chunks)}: start/end time {record.message_start_time}/"
                                 f"{record.message_end_time}, its messages {min(times)}/{max(times)}")
            chunks.append((record.message_start_time, record.message_end_time, len(times)))
        elif isinstance(record, Metadata):
            metadata[record.name] = record.metadata
        elif isinstance(record, DataEnd):
            data_end = record
            in_summary = True
        elif isinstance(record, Statistics):
            statistics = record
        elif isinstance(record, ChunkIndex):
            chunk_indexes.append(record)
        elif isinstance(record, Footer):
            footer = record
        elif isinstance(record, MessageIndex):
            pass
    if header is None or header.library == "":
        raise ValueError("no header library (doctor: warning)")
    if header.profile not in WELL_KNOWN_PROFILES:
        raise ValueError(f"header profile {header.profile!r} is not a well-known one (doctor: warning)")
    if data_end is None or footer is None:
        raise ValueError("no data end or footer")
    check_summary_crc(data, len(data) - len(MAGIC) - (1 + 8 + 8 + 8 + 4), footer)
    if statistics is None:
        raise ValueError("no statistics in the summary")
    total = sum(counts.values())
    if statistics.message_count != total:
        raise ValueError(f"read {total} messages, statistics say {statistics.message_count}")
    if dict(statistics.channel_message_counts) != dict(counts):
        raise ValueError(f"messages per channel {dict(counts)}, statistics say {statistics.channel_message_counts}")
    if total and (statistics.message_start_time, statistics.message_end_time) != (min_time, max_time):
        raise ValueError(f"statistics times {statistics.message_start_time}..{statistics.message_end_time}, "
                         f"messages {min_time}..{max_time}")
    if statistics.chunk_count != len(chunks) or len(chunk_indexes) != len(chunks):
        raise ValueError(f"{len(chunks)} chunks, statistics say {statistics.chunk_count}, "
                         f"{len(chunk_indexes)} chunk indexes")
    for i, (ci, c) in enumerate(zip(sorted(chunk_indexes, key=lambda x: x.chunk_start_offset), chunks)):
        if data[ci.chunk_start_offset] != 0x06:
            raise ValueError(f"chunk index {i} points at no chunk ({ci.chunk_start_offset})")
        if (ci.message_start_time, ci.message_end_time) != c[:2]:
            raise ValueError(f"chunk index {i}: times {ci.message_start_time}..{ci.message_end_time}, chunk {c[:2]}")
    if summary_channels != {k: v for k, v in channels.items()} or summary_schemas != schemas:
        raise ValueError("the summary's schemas and channels are not the data section's")

    line = f"{path}: ok — {total} messages, {len(channels)} channels, {len(chunks)} chunks, every message to JSON"
    if "stagecraft.session" in metadata:
        if spy["events"]["opened"] != spy["events"]["closed"]:
            raise ValueError(f"{spy['events']['opened']} connections opened but {spy['events']['closed']} closed")
        line += f"; spy log: {spy['wire_bytes']} wire bytes gap-free, {spy['events']['opened']} connections" \
                + (f", {spy['json']} decoded JSON messages" if spy["json"] else "")
    print(line)


def self_test():
    """Each bad file must be rejected for its own reason, the good one accepted."""
    import os
    import tempfile
    from mcap.writer import CompressionType, Writer

    def make(path, times=(1000, 1001, 1002), schema=("t", "jsonschema", b"{}"), encoding="json", data=b'{"n":1}'):
        with open(path, "wb") as f:
            w = Writer(f, compression=CompressionType.NONE)
            w.start(profile="", library="mcap-check self-test")
            c = w.register_channel("/c", encoding, w.register_schema(*schema) if schema else 0)
            for i, t in enumerate(times):
                w.add_message(c, log_time=t, publish_time=t, data=data, sequence=i)
            w.finish()

    with tempfile.TemporaryDirectory() as d:
        good = os.path.join(d, "good.mcap")
        make(good)
        bad = {
            "strict message order": lambda p: make(p, times=(1000, 990, 1010)),
            "empty encoding": lambda p: make(p, schema=("player.Message", "", b""), encoding="x-player-xdr"),
            "mcap cat --json refuses": lambda p: make(p, schema=None, encoding="x-player-xdr"),
            "CRC": lambda p: (make(p), damage(p)),
        }

        def damage(p):
            with open(p, "r+b") as f:
                content = f.read()
                at = content.index(b'{"n":1}')  # inside the uncompressed chunk
                f.seek(at)
                f.write(b'{"n":2}')

        check(good)
        for why, build in bad.items():
            path = os.path.join(d, "bad.mcap")
            build(path)
            try:
                check(path)
            except Exception as e:  # the check must reject it, for this reason
                if why.lower() not in str(e).lower():
                    raise AssertionError(f"self-test: a file with {why} was rejected for another reason: {e}")
                continue
            raise AssertionError(f"self-test: a file with {why} was accepted")
    print(f"mcap-check self-test: a good file accepted, {len(bad)} bad ones rejected for their reasons")


def main(paths):
    if paths and paths[0] == "--self-test":
        self_test()
        paths = paths[1:]
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
