#!/usr/bin/python3
"""Minimal OPeNDAP DAP2 server for tests: serves the NetCDF files under --root on 127.0.0.1.

Responses: <path>.dds, <path>.das, <path>.dods (with an optional projection constraint),
<path>.ver and /version.  Variables are sent as plain DAP arrays (no Grid, no Sequence, no
Structure); only the root group is served.  See README.md beside this file.
"""
import argparse
import email.utils
import json
import os
import queue
import re
import select
import socket
import struct
import sys
import threading
import time
import urllib.parse
from concurrent.futures import Future
from http.server import BaseHTTPRequestHandler, ThreadingHTTPServer

try:
    import numpy as np
    import netCDF4
except ImportError:  # e.g. a pyenv python3 first on PATH: retry with Debian's interpreter
    if os.path.exists("/usr/bin/python3") and os.path.realpath(sys.executable) != os.path.realpath("/usr/bin/python3"):
        os.execv("/usr/bin/python3", ["/usr/bin/python3"] + sys.argv)
    raise

SERVER_VERSION = "ompl_glider-dap2-test/1.0"
SUFFIXES = (".dods", ".dds", ".das", ".ver")
# characters the NetCDF-C DDS/DAS lexers accept inside a word; anything else is %XX-escaped
WORD_CHARS = set("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789-+_/.*!~'")
# numpy dtype string -> (DAP type, XDR numpy dtype used to send the values)
DAP_TYPES = {
    "i1": ("Byte", "u1"), "u1": ("Byte", "u1"),
    "i2": ("Int16", ">i4"), "u2": ("UInt16", ">u4"),
    "i4": ("Int32", ">i4"), "u4": ("UInt32", ">u4"),
    "i8": ("Float64", ">f8"), "u8": ("Float64", ">f8"),  # DAP2 has no 64-bit integers
    "f4": ("Float32", ">f4"), "f8": ("Float64", ">f8"),
}


class DapError(Exception):
    def __init__(self, status, message):
        super().__init__(message)
        self.status = status
        self.message = message


def escape_name(name):
    return "".join(c if c in WORD_CHARS else "".join("%%%02X" % b for b in c.encode()) for c in name)


def quote_string(s):
    return '"' + s.replace("\\", "\\\\").replace('"', '\\"') + '"'


def error_body(status, message):
    return ("Error {\n    code = %d;\n    message = %s;\n};\n" % (status, quote_string(message))).encode()


class VarInfo:
    """How one NetCDF variable is presented in DAP2."""

    def __init__(self, var):
        self.var = var
        self.name = var.name
        self.dims = list(var.dimensions)
        self.shape = list(var.shape)
        self.is_char = False
        self.unsigned = False
        dt = var.dtype
        if dt is str:
            self.dap, self.xdr = "String", None
        elif isinstance(dt, np.dtype) and dt.kind == "S" and dt.itemsize == 1:
            self.dap, self.xdr, self.is_char = "String", None, True
        elif isinstance(dt, np.dtype) and dt.kind in "iuf" and dt.str[1:] in DAP_TYPES:
            self.dap, self.xdr = DAP_TYPES[dt.str[1:]]
            self.unsigned = dt.str[1:] in ("u1", "u2", "u4")
        else:
            raise ValueError("unsupported type %s" % dt)  # compound, vlen: skipped
        # DAP view of the dimensions: a char variable loses its last (string length) dimension
        self.dap_dims = self.dims[:-1] if self.is_char and self.dims else self.dims
        self.dap_shape = self.shape[:-1] if self.is_char and self.shape else self.shape


def dataset_vars(ds):
    out = {}
    for name, var in ds.variables.items():
        try:
            out[name] = VarInfo(var)
        except ValueError:
            pass
    return out


def parse_constraint(ce, infos):
    """Return [(VarInfo, [(start, stride, stop), ...] over all NetCDF dims)] in dataset order."""
    projection = ce.split("&", 1)[0].strip()  # selections (after &) are ignored
    if not projection:
        return [(vi, [(0, 1, n - 1) for n in vi.shape]) for vi in infos.values()]
    if "(" in projection:
        raise DapError(400, "server-side functions are not supported: %s" % projection)
    chosen = {}
    for item in projection.split(","):
        m = re.fullmatch(r"\s*([^\[\]]+?)\s*((?:\[[^\]]*\]\s*)*)", item)
        if not m:
            raise DapError(400, "malformed constraint item: %s" % item)
        name = m.group(1)
        for cand in (name, urllib.parse.unquote(name), name.rsplit(".", 1)[-1]):
            if cand in infos:
                name = cand
                break
        else:
            raise DapError(404, "no such variable: %s" % name)
        vi = infos[name]
        hyper = [(0, 1, n - 1) for n in vi.shape]
        groups = re.findall(r"\[([^\]]*)\]", m.group(2))
        if len(groups) > len(vi.shape) or (len(groups) > len(vi.dap_shape) and not vi.is_char):
            raise DapError(400, "too many indices for %s" % name)
        for k, g in enumerate(groups):
            try:
                parts = [int(p) for p in g.split(":")]
            except ValueError:
                raise DapError(400, "malformed index [%s] for %s" % (g, name))
            if len(parts) == 1:
                start, stride, stop = parts[0], 1, parts[0]
            elif len(parts) == 2:
                start, stride, stop = parts[0], 1, parts[1]
            elif len(parts) == 3:
                start, stride, stop = parts
            else:
                raise DapError(400, "malformed index [%s] for %s" % (g, name))
            if not (0 <= start <= stop < vi.shape[k]) or stride < 1:
                raise DapError(400, "index [%s] out of range for %s (size %d)" % (g, name, vi.shape[k]))
            hyper[k] = (start, stride, stop)
        chosen.setdefault(name, hyper)  # a repeated name keeps its first projection
    return [(infos[n], chosen[n]) for n in infos if n in chosen]


def counts(hyper):
    return [(stop - start) // stride + 1 for start, stride, stop in hyper]


def dds_text(ds_name, selected):
    lines = ["Dataset {"]
    for vi, hyper in selected:
        n = counts(hyper)
        dims = "".join("[%s = %d]" % (escape_name(d), c) for d, c in zip(vi.dap_dims, n))
        lines.append("    %s %s%s;" % (vi.dap, escape_name(vi.name), dims))
    lines.append("} %s;" % escape_name(ds_name))
    return "\n".join(lines) + "\n"


def fmt_value(dap, x):
    if dap == "String":
        return quote_string(x)
    if dap in ("Float32", "Float64"):
        x = float(x) if dap == "Float64" else np.float32(x)
        if np.isnan(x):
            return "NaN"
        if np.isinf(x):
            return "Inf" if x > 0 else "-Inf"
        return repr(x) if dap == "Float64" else str(x)
    if dap == "Byte":
        return str(int(x) & 0xFF)
    return str(int(x))


def attr_lines(name, value, indent):
    if isinstance(value, bytes):
        value = value.decode("utf-8", "replace")
    if isinstance(value, str):
        dap, vals = "String", [value]
    elif isinstance(value, (list, tuple)) or (isinstance(value, np.ndarray) and value.dtype.kind in "OUS"):
        dap, vals = "String", [v.decode() if isinstance(v, bytes) else str(v) for v in np.ravel(value)]
    else:
        arr = np.atleast_1d(np.asarray(value))
        key = arr.dtype.str[1:]
        if key in DAP_TYPES:  # int8 goes as Byte (x & 0xFF): NetCDF-C shows it as a signed byte again
            dap = DAP_TYPES[key][0]
        else:
            return []
        vals = list(arr)
    return ["%s%s %s %s;" % (indent, dap, escape_name(name), ", ".join(fmt_value(dap, v) for v in vals))]


def das_text(ds, infos):
    lines = ["Attributes {"]
    for vi in infos.values():
        lines.append("    %s {" % escape_name(vi.name))
        for a in vi.var.ncattrs():
            lines += attr_lines(a, vi.var.getncattr(a), " " * 8)
        if vi.unsigned and "_Unsigned" not in vi.var.ncattrs():  # NetCDF-C 4.9 turns them into signed types
            lines.append('        String _Unsigned "true";')
        if vi.is_char:  # flat names: NetCDF-C 4.9 moves a nested DODS {} container to the globals
            lines.append("        Int32 DODS.strlen %d;" % (vi.shape[-1] if vi.dims else 1))
            if vi.dims:
                lines.append("        String DODS.dimName %s;" % quote_string(vi.dims[-1]))
        lines.append("    }")
    lines.append("    NC_GLOBAL {")
    for a in ds.ncattrs():
        lines += attr_lines(a, ds.getncattr(a), " " * 8)
    lines.append("    }")
    unlimited = [d for d, dim in ds.dimensions.items() if dim.isunlimited()]
    if unlimited:
        lines += ["    DODS_EXTRA {", "        String Unlimited_Dimension %s;" % quote_string(unlimited[0]), "    }"]
    lines.append("}")
    return "\n".join(lines) + "\n"


def xdr_strings(strings):
    out = bytearray()
    for s in strings:
        b = s if isinstance(s, bytes) else str(s).encode("utf-8")
        out += struct.pack(">I", len(b)) + b + b"\0" * (-len(b) % 4)
    return bytes(out)


def xdr_var(vi, hyper):
    """Read the hyperslab of one variable and return its XDR encoding."""
    index = tuple(slice(start, stop + 1, stride) for start, stride, stop in hyper)
    data = np.asarray(vi.var[index] if index else vi.var[...])
    scalar = len(vi.dap_shape) == 0
    n = int(np.prod(counts(hyper[:len(vi.dap_shape)]))) if not scalar else 1
    if vi.dap == "String":
        if vi.is_char:  # join the characters of the last dimension, drop the NUL padding
            data = data.astype("S1")
            rows = data.reshape(-1, data.shape[-1]) if data.ndim else data.reshape(1, 1)
            data = np.array([b"".join(r).rstrip(b"\0") for r in rows], dtype=object)
        body = xdr_strings(np.ravel(data))
        return body if scalar else struct.pack(">I", n) + body
    if vi.dap == "Byte":
        raw = np.ascontiguousarray(data).view("u1").tobytes() if data.ndim else bytes([int(data) & 0xFF])
        if scalar:
            return struct.pack(">I", raw[0])
        return struct.pack(">II", n, n) + raw + b"\0" * (-len(raw) % 4)
    body = np.ascontiguousarray(data.astype(vi.xdr)).tobytes()
    return body if scalar else struct.pack(">II", n, n) + body


class Handler(BaseHTTPRequestHandler):
    protocol_version = "HTTP/1.1"
    disable_nagle_algorithm = True  # headers and body go in separate writes: avoid the 40 ms delayed-ACK stall
    server_version = SERVER_VERSION

    def log_message(self, fmt, *args):  # quiet: the JSON log is the record
        pass

    def do_GET(self):
        self.handle_request(send_body=True)

    def do_HEAD(self):
        self.handle_request(send_body=False)

    def handle_request(self, send_body):
        cfg = self.server.cfg
        raw_path, _, raw_query = self.path.partition("?")
        path = urllib.parse.unquote(raw_path)
        query = urllib.parse.unquote(raw_query)
        rec = {"time": round(time.time(), 3), "method": self.command, "path": path, "query": query,
               "status": 0, "bytes": 0, "data_bytes": 0, "variables": {}}
        headers = {}
        try:
            if cfg.fail_status:
                raise DapError(cfg.fail_status, "forced failure (--fail-status %d)" % cfg.fail_status)
            status, desc, ctype, body, data_bytes = self.respond(path, query, rec, headers)
        except DapError as e:
            status, desc, ctype, body, data_bytes = e.status, "dods_error", "text/plain", error_body(e.status, e.message), 0
        except Exception as e:  # noqa: BLE001 - report anything as a DAP error, never crash
            status, desc, ctype, body, data_bytes = 500, "dods_error", "text/plain", error_body(500, "%s: %s" % (type(e).__name__, e)), 0
        rec.update(status=status, bytes=len(body), data_bytes=data_bytes)
        if self.client_gone():  # e.g. the client timed out during --delay: nothing is sent
            rec["client_gone"] = True
            self.close_connection = True
            self.server.record(rec)
            return
        try:
            self.send_response(status)
            self.send_header("Content-Type", ctype)
            self.send_header("Content-Description", desc)
            self.send_header("XDODS-Server", "dods/3.2")
            self.send_header("XOPeNDAP-Server", SERVER_VERSION)
            self.send_header("XDAP", "2.0")
            for k, v in headers.items():
                self.send_header(k, v)
            if cfg.truncate > 0 and desc == "dods_data":
                # a data answer cut short: the XDR part ends early, the length header says so ("short") or
                # promises the whole ("cut": the connection closes before it)
                cut = body[:len(body) - max(1, int(cfg.truncate * data_bytes))]
                self.send_header("Content-Length", str(len(cut) if cfg.truncate_mode == "short" else len(body)))
                self.end_headers()
                if send_body:
                    self.wfile.write(cut)
                self.wfile.flush()
                self.close_connection = True
                self.server.record(dict(rec, truncated=len(body) - len(cut)))
                return
            self.send_header("Content-Length", str(len(body)))
            self.end_headers()
            if send_body:
                self.wfile.write(body)
            self.wfile.flush()
        except (BrokenPipeError, ConnectionResetError) as e:
            rec["client_gone"] = type(e).__name__
        self.server.record(rec)

    def client_gone(self):
        try:
            readable = select.select([self.connection], [], [], 0)[0]
            return bool(readable) and self.connection.recv(1, socket.MSG_PEEK) == b""
        except OSError:
            return True

    def respond(self, path, query, rec, headers):
        cfg = self.server.cfg
        if path in ("/version", "/version/"):
            return 200, "dods_version", "text/plain", ("Core version: DAP/2.0\nServer version: %s\n" % SERVER_VERSION).encode(), 0
        suffix = next((s for s in SUFFIXES if path.endswith(s)), None)
        if suffix is None:
            raise DapError(404, "unsupported request %s: use .dds, .das, .dods or .ver" % path)
        rel = path[: -len(suffix)].lstrip("/")
        full = os.path.realpath(os.path.join(cfg.root, rel))
        if not rel or not full.startswith(cfg.root + os.sep) or not os.path.isfile(full):
            raise DapError(404, "no such dataset: /%s" % rel)
        if suffix == ".ver":
            return 200, "dods_version", "text/plain", ("Core version: DAP/2.0\nServer version: %s\n" % SERVER_VERSION).encode(), 0
        if suffix == ".dods" and cfg.delay > 0:
            self.server.stop_event.wait(cfg.delay)
        headers["Last-Modified"] = email.utils.formatdate(os.path.getmtime(full), usegmt=True)
        return self.server.run_nc(lambda: dataset_response(full, rel, suffix, query, rec))


def dataset_response(full, rel, suffix, query, rec):
    """Build a .das/.dds/.dods answer; runs on the main thread (see Server.run_nc)."""
    try:
        ds = netCDF4.Dataset(full, "r")
    except OSError as e:
        raise DapError(404, "not a NetCDF file: /%s (%s)" % (rel, e))
    try:
        ds.set_auto_maskandscale(False)
        ds.set_auto_chartostring(False)
        infos = dataset_vars(ds)
        if suffix == ".das":
            return 200, "dods_das", "text/plain", das_text(ds, infos).encode(), 0
        selected = parse_constraint(query, infos)
        if suffix == ".dods" or query.split("&", 1)[0].strip():
            rec["variables"] = {vi.name: counts(h) for vi, h in selected}
            rec["hyperslabs"] = {vi.name: "".join("[%d:%d:%d]" % t for t in h) for vi, h in selected}
        dds = dds_text(os.path.basename(rel), selected).encode()
        if suffix == ".dds":
            return 200, "dods_dds", "text/plain", dds, 0
        xdr = b"".join(xdr_var(vi, h) for vi, h in selected)
        return 200, "dods_data", "application/octet-stream", dds + b"\nData:\n" + xdr, len(xdr)
    finally:
        ds.close()


class Server(ThreadingHTTPServer):
    daemon_threads = True

    def __init__(self, cfg):
        super().__init__(("127.0.0.1", cfg.port), Handler)
        self.cfg = cfg
        self.stop_event = threading.Event()
        self.log_lock = threading.Lock()
        self.nrequests = 0
        self.jobs = queue.Queue()

    def run_nc(self, fn):
        """Run fn on the main thread: netCDF-C/HDF5 are not thread-safe, and HDF5 prints
        error-stack noise for lookups done on other threads."""
        fut = Future()
        self.jobs.put((fn, fut))
        return fut.result()

    def work_until_stopped(self, lifetime):
        deadline = time.monotonic() + lifetime
        while not self.stop_event.is_set():
            remaining = deadline - time.monotonic()
            if remaining <= 0:
                return False
            try:
                fn, fut = self.jobs.get(timeout=min(remaining, 0.2))
            except queue.Empty:
                continue
            try:
                fut.set_result(fn())
            except BaseException as e:  # noqa: BLE001 - handed to the waiting request thread
                fut.set_exception(e)
        return True

    def record(self, rec):
        with self.log_lock:
            if self.cfg.log:
                with open(self.cfg.log, "a") as f:
                    f.write(json.dumps(rec) + "\n")
                    f.flush()
            self.nrequests += 1
            if self.cfg.max_requests and self.nrequests >= self.cfg.max_requests:
                self.stop_event.set()


def write_port_file(path, port):
    tmp = "%s.tmp.%d" % (path, os.getpid())
    with open(tmp, "w") as f:
        f.write("%d\n" % port)
    os.replace(tmp, path)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--root", required=True, help="directory whose NetCDF files are served")
    ap.add_argument("--port", type=int, default=0, help="TCP port on 127.0.0.1 (0: any free port)")
    ap.add_argument("--port-file", help="write the chosen port here (atomically) once listening")
    ap.add_argument("--log", help="append one JSON line per request to this file")
    ap.add_argument("--delay", type=float, default=0.0, help="sleep this many seconds before each .dods answer")
    ap.add_argument("--fail-status", type=int, default=0, help="answer every request with this HTTP status")
    ap.add_argument("--truncate", type=float, default=0.0,
                    help="cut this fraction of the XDR data off each .dods answer (0: whole answers)")
    ap.add_argument("--truncate-mode", choices=("short", "cut"), default="short",
                    help="short: the Content-Length header gives the cut length; cut: it promises the whole")
    ap.add_argument("--max-requests", type=int, default=0, help="exit after this many requests (0: no limit)")
    ap.add_argument("--lifetime", type=float, default=600.0, help="exit after this many seconds (default 600)")
    cfg = ap.parse_args(argv)
    cfg.root = os.path.realpath(cfg.root)
    if not os.path.isdir(cfg.root):
        ap.error("--root %s is not a directory" % cfg.root)
    if cfg.lifetime <= 0:
        ap.error("--lifetime must be positive")
    if cfg.port_file and os.path.exists(cfg.port_file):
        os.remove(cfg.port_file)
    server = Server(cfg)
    port = server.server_address[1]
    if cfg.port_file:
        write_port_file(cfg.port_file, port)
    print("dap2_server: serving %s at http://127.0.0.1:%d/" % (cfg.root, port), file=sys.stderr, flush=True)
    thread = threading.Thread(target=server.serve_forever, kwargs={"poll_interval": 0.2}, daemon=True)
    thread.start()
    try:
        stopped = server.work_until_stopped(cfg.lifetime)
    except KeyboardInterrupt:
        stopped = True
    server.stop_event.set()  # wakes delayed handlers
    server.shutdown()
    server.server_close()
    print("dap2_server: exiting (%s)" % ("stopped" if stopped else "lifetime over"), file=sys.stderr, flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
