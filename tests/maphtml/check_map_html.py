#!/usr/bin/env python3
"""check_map_html.py MAP.html [--expect-routes N] [--expect-route-vertices N,N..]
    [--expect-popup-text TEXT]... [--expect-isochrones N] [--expect-land-min N]
    [--expect-current-frames N] [--expect-tracks N] [--expect-fleet-ends-min N] [--expect-reach-frames N]
    [--screenshot OUT.png] [--timeout S]

Opens MAP.html in Debian's headless Chromium, offline (DevTools network
emulation), over the Chrome DevTools Protocol (python3-websocket). Fails on any
console error, uncaught exception, failed request, unmet expectation, a time
slider that does not change the shown frame (the current's; the probability of
reach's, whose drawing must change too), or a blank screenshot.
Exit 0 on pass, 1 on failure (2 on usage errors)."""
import argparse
import base64
import html
import json
import os
import re
import shutil
import signal
import struct
import subprocess
import sys
import tempfile
import time
import urllib.request
import zlib

try:
    import websocket  # Debian: python3-websocket (websocket-client)
except ImportError:  # e.g. a pyenv python first on PATH: retry with Debian's
    if os.path.exists('/usr/bin/python3') and os.path.realpath(sys.executable) != os.path.realpath('/usr/bin/python3'):
        os.execv('/usr/bin/python3', ['/usr/bin/python3'] + sys.argv)
    sys.exit('check_map_html: needs python3-websocket (apt-get install python3-websocket)')

CHROMIUM = '/usr/bin/chromium'
W, H = 1200, 800


class Timeout(Exception):
    pass


class CDP:
    def __init__(self, ws_url, deadline):
        self.ws = websocket.create_connection(ws_url, timeout=10, suppress_origin=True)
        self.deadline, self.next_id, self.events = deadline, 0, []

    def call(self, method, **params):
        self.next_id += 1
        mid = self.next_id
        self.ws.send(json.dumps({'id': mid, 'method': method, 'params': params}))
        while True:
            msg = self._recv(max(0.1, self.deadline - time.time()))
            if msg is None:
                raise Timeout('no answer to ' + method)
            if msg.get('id') == mid:
                if 'error' in msg:
                    raise RuntimeError('%s: %s' % (method, msg['error']))
                return msg.get('result', {})
            if 'method' in msg:
                self.events.append(msg)

    def _recv(self, wait):
        self.ws.settimeout(min(wait, 10))
        try:
            return json.loads(self.ws.recv())
        except websocket.WebSocketTimeoutException:
            return None

    def pump(self, seconds):  # collect events for a while
        end = time.time() + seconds
        while time.time() < end:
            msg = self._recv(max(0.01, end - time.time()))
            if msg and 'method' in msg:
                self.events.append(msg)

    def eval(self, expr):
        r = self.call('Runtime.evaluate', expression=expr, returnByValue=True, awaitPromise=True)
        if 'exceptionDetails' in r:
            raise RuntimeError('evaluate failed: %s' % r['exceptionDetails'].get('text'))
        return r.get('result', {}).get('value')


def start_chromium(profile, deadline):
    cmd = [CHROMIUM, '--headless=new', '--no-sandbox', '--disable-gpu', '--remote-debugging-port=0',
           '--user-data-dir=' + profile, '--window-size=%d,%d' % (W, H), '--no-first-run',
           '--no-default-browser-check', '--disable-extensions', '--disable-background-networking',
           '--disable-component-update', '--disable-sync', '--disable-default-apps', 'about:blank']
    proc = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, start_new_session=True)
    port_file = os.path.join(profile, 'DevToolsActivePort')
    while time.time() < deadline:
        if proc.poll() is not None:
            raise RuntimeError('chromium exited with code %s at start' % proc.returncode)
        if os.path.exists(port_file):
            lines = open(port_file).read().split()
            if len(lines) >= 2:
                return proc, int(lines[0])
        time.sleep(0.1)
    raise Timeout('chromium did not write DevToolsActivePort')


def page_ws_url(port, deadline):
    while time.time() < deadline:
        try:
            with urllib.request.urlopen('http://127.0.0.1:%d/json/list' % port, timeout=3) as r:
                pages = [t for t in json.load(r) if t.get('type') == 'page']
            if pages:
                return pages[0]['webSocketDebuggerUrl']
        except OSError:
            pass
        time.sleep(0.2)
    raise Timeout('no page target in chromium')


def kill(proc):
    if proc and proc.poll() is None:
        try:
            os.killpg(proc.pid, signal.SIGTERM)  # its own session: chromium and its helpers only
            proc.wait(5)
        except (ProcessLookupError, subprocess.TimeoutExpired):
            try:
                os.killpg(proc.pid, signal.SIGKILL)
            except ProcessLookupError:
                pass


def png_stats(data):
    """(width, height, fraction of pixels differing from the most common colour, distinct colours)."""
    if data[:8] != b'\x89PNG\r\n\x1a\n':
        raise ValueError('not a PNG')
    pos, idat, hdr = 8, [], None
    while pos < len(data):
        n, typ = struct.unpack('>I4s', data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + n]
        pos += 12 + n
        if typ == b'IHDR':
            hdr = struct.unpack('>IIBBBBB', body)
        elif typ == b'IDAT':
            idat.append(body)
    w, h, depth, ctype, _, _, interlace = hdr
    if depth != 8 or ctype not in (2, 6) or interlace:
        raise ValueError('unsupported PNG format %s' % (hdr,))
    bpp = 3 if ctype == 2 else 4
    raw, stride = zlib.decompress(b''.join(idat)), w * bpp
    prev, counts = bytearray(stride), {}
    for y in range(h):
        f, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        if f == 1:
            for i in range(bpp, stride):
                line[i] = (line[i] + line[i - bpp]) & 255
        elif f == 2:
            line = bytearray((a + b) & 255 for a, b in zip(line, prev))
        elif f == 3:
            for i in range(stride):
                line[i] = (line[i] + ((line[i - bpp] if i >= bpp else 0) + prev[i]) // 2) & 255
        elif f == 4:
            for i in range(stride):
                a = line[i - bpp] if i >= bpp else 0
                b, c = prev[i], prev[i - bpp] if i >= bpp else 0
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        if y % 2 == 0:  # every other row and column is plenty for statistics
            for x in range(0, stride, 2 * bpp):
                key = bytes(line[x:x + 3])
                counts[key] = counts.get(key, 0) + 1
        prev = line
    total = sum(counts.values())
    return w, h, 1 - max(counts.values()) / total, len(counts)


def event_errors(events):
    out = []
    for e in events:
        m, p = e['method'], e.get('params', {})
        if m == 'Runtime.consoleAPICalled' and p.get('type') in ('error', 'assert'):
            out.append('console.%s: %s' % (p['type'], ' '.join(str(a.get('value', a.get('description', ''))) for a in p.get('args', []))))
        elif m == 'Runtime.exceptionThrown':
            d = p.get('exceptionDetails', {})
            out.append('exception: %s %s (line %s)' % (d.get('text', ''), d.get('exception', {}).get('description', ''), d.get('lineNumber')))
        elif m == 'Log.entryAdded' and p.get('entry', {}).get('level') == 'error':
            out.append('log error: %s %s' % (p['entry'].get('text'), p['entry'].get('url', '')))
        elif m == 'Network.loadingFailed' and not p.get('canceled'):
            out.append('failed request: %s (%s)' % (p.get('errorText'), p.get('requestId')))
        elif m == 'Network.requestWillBeSent':
            url = p.get('request', {}).get('url', '')
            if not url.startswith(('file:', 'data:', 'about:')):
                out.append('request to outside the file: %s' % url)
    return out


def run(a):
    deadline = time.time() + a.timeout
    fails, info = [], {}
    path = os.path.abspath(a.map)
    if not os.path.isfile(path):
        return ['no such file: ' + path], info
    profile = tempfile.mkdtemp(prefix='maphtml-chromium-')
    proc = None
    try:
        proc, port = start_chromium(profile, deadline)
        cdp = CDP(page_ws_url(port, deadline), deadline)
        for dom in ('Runtime', 'Log', 'Page', 'Network'):
            cdp.call(dom + '.enable')
        cdp.call('Network.emulateNetworkConditions', offline=True, latency=0, downloadThroughput=-1, uploadThroughput=-1)
        cdp.call('Emulation.setDeviceMetricsOverride', width=W, height=H, deviceScaleFactor=1, mobile=False)
        cdp.call('Page.navigate', url='file://' + path)
        t0 = time.time()
        ready_by, state = min(deadline, t0 + a.ready_timeout), None
        while time.time() < ready_by:
            cdp.pump(0.25)
            if cdp.eval('!!(window.GLIDER_MAP_STATE && window.GLIDER_MAP_STATE.ready)'):
                state = json.loads(cdp.eval('JSON.stringify(window.GLIDER_MAP_STATE)'))
                break
        if state is None:
            fails.append('window.GLIDER_MAP_STATE.ready not true within %.1f s' % (time.time() - t0))
            return fails + event_errors(cdp.events), info
        info['state'] = state
        nv, popups = state.get('routeVertices', []), state.get('waypointPopups', [])
        texts = [html.unescape(re.sub(r'<[^>]+>', ' ', p)) for p in popups]
        texts = [re.sub(r'\s+', ' ', t) for t in texts]
        if a.expect_routes is not None and len(nv) != a.expect_routes:
            fails.append('routes: expected %d, page has %d' % (a.expect_routes, len(nv)))
        if a.expect_route_vertices is not None:
            want = [int(x) for x in a.expect_route_vertices.split(',') if x.strip()]
            if want != nv:
                fails.append('route vertices: expected %s, page has %s' % (want, nv))
        for t in a.expect_popup_text or []:
            if not any(t in p or t in q for p, q in zip(popups, texts)):
                fails.append('no waypoint popup contains %r (%d popups)' % (t, len(popups)))
        for key, want, cmp in (('isochroneCount', a.expect_isochrones, 'eq'), ('landCount', a.expect_land_min, 'min'),
                               ('currentFrames', a.expect_current_frames, 'eq'),
                               ('trackCount', a.expect_tracks, 'eq'),
                               ('fleetEnds', a.expect_fleet_ends_min, 'min')):
            got = state.get(key)
            if want is not None and (got is None or (got != want if cmp == 'eq' else got < want)):
                fails.append('%s: expected %s%d, page has %s' % (key, '>= ' if cmp == 'min' else '', want, got))
        if state.get('problems'):
            fails.append('page reported problems: %s' % state['problems'])
        frames = state.get('currentFrames', 0)
        if frames and state.get('sliderMax') != frames - 1:
            fails.append('sliderMax %s != frames-1 (%d)' % (state.get('sliderMax'), frames - 1))
        if frames and not state.get('currentArrowsShown'):
            print('WARN: no current arrows shown in frame 0 (all zero or invalid?)')
        if frames >= 2:
            moved = cdp.eval("""(() => { const s = document.getElementById('frame-slider'),
                l = document.getElementById('frame-time'); const before = l.textContent;
                s.value = s.max; s.dispatchEvent(new Event('input', {bubbles: true}));
                return {before, after: l.textContent, idx: window.GLIDER_MAP_STATE.currentFrameIndex,
                        arrows: window.GLIDER_MAP_STATE.currentArrowsShown}; })()""")
            info['slider'] = moved
            if moved['before'] == moved['after'] or not moved['after']:
                fails.append('time slider: shown frame date did not change (%r -> %r)' % (moved['before'], moved['after']))
            if moved['idx'] != frames - 1:
                fails.append('time slider: state.currentFrameIndex %s != %d' % (moved['idx'], frames - 1))
        if a.expect_reach_frames is not None:
            n = state.get('reachFrames')
            if n != a.expect_reach_frames:
                fails.append('reachFrames: expected %d, page has %s' % (a.expect_reach_frames, n))
            if not state.get('reachImages') or not state.get('reachContourVertices'):
                fails.append('probability of reach: no image or no contour drawn (%s, %s)' % (
                    state.get('reachImages'), state.get('reachContourVertices')))
            if state.get('reachFrameIndex') != (n or 0) - 1 or state.get('reachSliderMax') != (n or 0) - 1:
                fails.append('probability of reach: starts at frame %s of slider max %s, not the last (%s)' % (
                    state.get('reachFrameIndex'), state.get('reachSliderMax'), (n or 0) - 1))
            if n and n >= 2:
                moved = cdp.eval("""(() => { const s = document.getElementById('reach-slider');
                    const st = () => { const g = window.GLIDER_MAP_STATE; return {idx: g.reachFrameIndex,
                        time: g.reachFrameTime, sum: g.reachPercentSum, vertices: g.reachContourVertices}; };
                    const before = st(); s.value = 0; s.dispatchEvent(new Event('input', {bubbles: true}));
                    return {before, after: st()}; })()""")
                info['reach'] = moved
                b, f = moved['before'], moved['after']
                if f['idx'] != 0:
                    fails.append('probability of reach slider: frame index %s, expected 0' % f['idx'])
                if b['time'] == f['time'] or not f['time']:
                    fails.append('probability of reach slider: shown date did not change (%r -> %r)' % (b['time'], f['time']))
                if b['sum'] == f['sum'] and b['vertices'] == f['vertices']:
                    fails.append('probability of reach slider: the drawing did not change (%s)' % f)
                if not f['sum'] < b['sum']:
                    fails.append('probability of reach: the first frame reaches no less than the last (%s -> %s)' % (
                        b['sum'], f['sum']))
        cdp.pump(0.5)
        shot = base64.b64decode(cdp.call('Page.captureScreenshot', format='png',
                                         clip={'x': 0, 'y': 0, 'width': W, 'height': H, 'scale': 1})['data'])
        if a.screenshot:
            open(a.screenshot, 'wb').write(shot)
        w, h, frac, ncol = png_stats(shot)
        info['screenshot'] = '%dx%d, %.1f%% non-background, %d colours' % (w, h, 100 * frac, ncol)
        if frac < 0.03 or ncol < 8:
            fails.append('screenshot looks blank: ' + info['screenshot'])
        cdp.pump(0.2)
        return fails + event_errors(cdp.events), info
    finally:
        kill(proc)
        shutil.rmtree(profile, ignore_errors=True)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    ap.add_argument('map')
    ap.add_argument('--expect-routes', type=int)
    ap.add_argument('--expect-route-vertices')
    ap.add_argument('--expect-popup-text', action='append', metavar='TEXT')
    ap.add_argument('--expect-isochrones', type=int)
    ap.add_argument('--expect-tracks', type=int, help='flown tracks drawn (an execution run)')
    ap.add_argument('--expect-fleet-ends-min', type=int, help="other gliders' own start and goal markers (a fleet)")
    ap.add_argument('--expect-land-min', type=int)
    ap.add_argument('--expect-reach-frames', type=int, help='frames of the probability of reach (its own slider)')
    ap.add_argument('--expect-current-frames', type=int)
    ap.add_argument('--screenshot')
    ap.add_argument('--timeout', type=float, default=60, help='whole run, seconds (default 60)')
    ap.add_argument('--ready-timeout', type=float, default=20, help='wait for state.ready, seconds (default 20)')
    a = ap.parse_args()
    if not os.access(CHROMIUM, os.X_OK):
        sys.exit('check_map_html: %s missing (apt-get install chromium)' % CHROMIUM)

    def on_alarm(*_):
        raise Timeout('whole run exceeded %g s' % a.timeout)
    signal.signal(signal.SIGALRM, on_alarm)
    signal.alarm(int(a.timeout) + 5)
    try:
        fails, info = run(a)
    except Exception as e:  # noqa: BLE001 - every failure is reported the same way
        fails, info = ['%s: %s' % (type(e).__name__, e)], {}
    finally:
        signal.alarm(0)
    for f in fails:
        print('FAIL: ' + f)
    s = info.get('state', {})
    print('map.html check %s: %s | routes %s vertices %s popups %d isochrones %s land %s frames %s arrows %s->%s reach %s '
          'base %s | %s%s' % (
        'PASS' if not fails else 'FAILED (%d)' % len(fails), os.path.basename(a.map), len(s.get('routeVertices', [])),
        s.get('routeVertices'), len(s.get('waypointPopups', [])), s.get('isochroneCount'), s.get('landCount'),
        s.get('currentFrames'), s.get('currentArrowsShown'), info.get('slider', {}).get('arrows', '-'),
        s.get('reachFrames', '-'),
        s.get('baseMap'), info.get('screenshot', 'no screenshot'), (' -> ' + a.screenshot) if a.screenshot and 'screenshot' in info else ''))
    sys.exit(1 if fails else 0)


if __name__ == '__main__':
    main()
