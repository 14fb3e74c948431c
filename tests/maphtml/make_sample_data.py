#!/usr/bin/env python3
"""Regenerates sample_data.json (geographic fleet, Balearic Sea) and
sample_data_xy.json (planning frame in km) next to this script.
Synthetic data in the map.html schema; nothing here is a real forecast."""
import datetime as dt
import json
import math
import os

HERE = os.path.dirname(os.path.abspath(__file__))
T0 = dt.datetime(2026, 3, 15, 6, 0, tzinfo=dt.timezone.utc)


def iso(t):
    return t.strftime('%Y-%m-%dT%H:%M:%SZ')


def dhm(sec):
    m = int(round(sec / 60))
    return '%d d %02d:%02d' % (m // 1440, m % 1440 // 60, m % 60)


def inside(p, ring):
    y, x, c = p[0], p[1], False
    for (y1, x1), (y2, x2) in zip(ring, ring[1:] + ring[:1]):
        if (y1 > y) != (y2 > y) and x < (x2 - x1) * (y - y1) / (y2 - y1) + x1:
            c = not c
    return c


def inflate(ring, d, kx=1.0):
    cy = sum(p[0] for p in ring) / len(ring)
    cx = sum(p[1] for p in ring) / len(ring)
    out = []
    for y, x in ring:
        dy, dx = y - cy, (x - cx) / kx
        r = math.hypot(dy, dx) or 1
        out.append([round(y + d * dy / r, 5), round(x + d * dx / r * kx, 5)])
    return out


def densify(ctrl, step):
    pts = [ctrl[0]]
    for a, b in zip(ctrl, ctrl[1:]):
        n = max(1, int(math.hypot(b[0] - a[0], b[1] - a[1]) / step))
        pts += [[a[0] + (b[0] - a[0]) * i / n, a[1] + (b[1] - a[1]) * i / n] for i in range(1, n + 1)]
    return [[round(p[0], 5), round(p[1], 5)] for p in pts]


# ------------------------------------------------------------------ geographic
ISLANDS = [
    [[39.96, 3.20], [39.87, 3.20], [39.83, 3.13], [39.77, 3.20], [39.75, 3.35], [39.70, 3.47], [39.55, 3.40],
     [39.40, 3.30], [39.30, 3.10], [39.37, 2.95], [39.50, 2.75], [39.55, 2.60], [39.50, 2.40], [39.60, 2.35],
     [39.75, 2.60], [39.85, 2.80], [39.92, 2.95]],
    [[40.08, 3.80], [40.06, 4.05], [40.05, 4.30], [39.95, 4.30], [39.85, 4.10], [39.90, 3.82]],
    [[39.12, 1.40], [39.05, 1.62], [38.90, 1.60], [38.85, 1.38], [38.97, 1.22]],
]


def current_geo(lat, lon, hours):
    ey, ex = 39.2 + 0.002 * hours, 2.3 + 0.004 * hours            # drifting anticyclonic eddy
    dy, dx = lat - ey, (lon - ex) * math.cos(math.radians(lat))
    r = math.hypot(dy, dx)
    w = 0.55 * (r / 0.3) * math.exp(0.5 * (1 - (r / 0.3) ** 2))
    u, v = (w * dy / r, -w * dx / r) if r > 1e-9 else (0.0, 0.0)
    u += 0.12 + 0.05 * math.sin(hours / 12)                        # background drift, tidal wobble
    v += 0.18 * math.exp(-((lat - 40.3) / 0.2) ** 2) * -1.0 + 0.04  # southward jet in the north
    return u, v


def metres(a, b):
    k = math.cos(math.radians((a[0] + b[0]) / 2))
    return 111195.0 * math.hypot(b[0] - a[0], (b[1] - a[1]) * k)


def route_geo(name, ctrl):
    pts = densify(ctrl, 0.09)
    t, wps = 0.0, []
    for i, p in enumerate(pts):
        if i:
            t += metres(pts[i - 1], p) / 0.38
        if i % 3 == 0 or i == len(pts) - 1:
            q = pts[min(i + 1, len(pts) - 1)] if i < len(pts) - 1 else p
            r = pts[i - 1] if i == len(pts) - 1 else p
            hd = (math.degrees(math.atan2((q[1] - r[1]) * math.cos(math.radians(p[0])), q[0] - r[0])) + 360) % 360
            u, v = current_geo(p[0], p[1], t / 3600)
            wps.append({'index': i, 'lat': p[0], 'lon': p[1], 'arrival': iso(T0 + dt.timedelta(seconds=t)),
                        'elapsed': dhm(t), 'heading_deg': None if i == len(pts) - 1 else round(hd, 1),
                        'current': {'u': round(u, 3), 'v': round(v, 3), 'speed': round(math.hypot(u, v), 3),
                                    'dir_deg': round((math.degrees(math.atan2(u, v)) + 360) % 360, 1)}})
    return {'name': name, 'points': pts, 'waypoints': wps, 'travel_time': dhm(t)}, t


def geographic():
    start, goal = [39.0, 1.9], [40.3, 4.2]
    ra, ta = route_geo('glider A', [start, [39.55, 2.05], [39.95, 2.6], [40.15, 3.3], [40.28, 3.9], goal])
    rb, tb = route_geo('glider B', [start, [38.98, 2.5], [39.0, 3.2], [39.3, 3.55], [39.75, 3.65],
                                    [40.05, 3.68], [40.2, 3.8], goal])
    frames = []
    for hours in (0, 36, 72):
        arrows = []
        for i in range(19):
            for j in range(25):
                lat, lon = round(38.8 + 0.1 * i, 4), round(1.6 + 0.125 * j, 4)
                if any(inside([lat, lon], isl) for isl in ISLANDS):
                    continue
                u, v = current_geo(lat, lon, hours)
                arrows.append([lat, lon, round(u, 3), round(v, 3)])
        frames.append({'time': iso(T0 + dt.timedelta(hours=hours)), 'arrows': arrows})
    max_speed = max(math.hypot(a[2], a[3]) for f in frames for a in f['arrows'])
    isochrones = []
    for h in range(24, 24 * 9, 24):
        r = 0.38 * h * 3600 / 111195.0
        lines, cur = [], []
        for k in range(0, 91):
            ang = math.radians(k)
            p = [start[0] + r * math.sin(ang) * (1 + 0.06 * math.sin(5 * ang)),
                 start[1] + r * math.cos(ang) / math.cos(math.radians(39.5)) * (1 + 0.1 * math.cos(3 * ang))]
            ok = 38.8 <= p[0] <= 40.6 and 1.6 <= p[1] <= 4.6 and not any(inside(p, isl) for isl in ISLANDS)
            if ok:
                cur.append([round(p[0], 4), round(p[1], 4)])
            elif len(cur) > 1:
                lines.append(cur)
            if not ok:
                cur = []
        if len(cur) > 1:
            lines.append(cur)
        if lines:
            isochrones.append({'time': iso(T0 + dt.timedelta(hours=h)), 'lines': lines})
    track = [[round(p[0] + 0.012 * math.sin(i * 0.9), 5), round(p[1] + 0.015 * math.cos(i * 0.7) + 0.004 * i, 5)]
             for i, p in enumerate(ra['points'][: int(len(ra['points']) * 0.6)])]
    k = math.cos(math.radians(39.5))
    return {
        'title': 'Balearic crossing — fleet of 2 (sample)', 'geographic': True, 'units': '',
        'routes': [ra, rb], 'start': start, 'goal': goal, 'goal_tolerance': 5000,
        'isochrones': isochrones,
        'land': [[[round(a, 5), round(b, 5)] for a, b in isl] for isl in ISLANDS],
        'coastlines': [[[round(a, 5), round(b, 5)] for a, b in isl + isl[:1]] for isl in ISLANDS],
        'forbidden': [
            {'name': 'Military exercise area R-71', 'windows': [[iso(T0 + dt.timedelta(hours=18)), iso(T0 + dt.timedelta(hours=54))]],
             'rings': [[[39.6, 1.75], [39.8, 1.75], [39.8, 2.0], [39.6, 2.0]]]},
            {'name': 'Cabrera marine reserve </script><!-- escaping test', 'windows': [],
             'rings': [[[39.08, 2.85], [39.25, 2.85], [39.25, 3.05], [39.08, 3.05]]]},
        ],
        'keep_off': [inflate(isl, 0.05, 1 / k) for isl in ISLANDS],
        'tracks': [{'name': 'flown (strategy replan-6h)', 'points': track}],
        'currents': {'units': 'm/s', 'max_speed': round(max_speed, 3), 'frames': frames},
        'bounds': [[38.8, 1.6], [40.6, 4.6]],
    }


# ------------------------------------------------------------------ planning frame (km)
def planar():
    island = [[y * 1.0, x * 1.0] for y in range(40, 81, 5) for x in range(85, 121, 5)
              if math.hypot(y + 2.5 - 60, (x + 2.5 - 102) * 0.8) < 18]
    cells = [[[y, x], [y + 5, x], [y + 5, x + 5], [y, x + 5]] for y, x in island]
    ring = [[round(60 + 26 * math.sin(a / 20 * math.pi), 3), round(102 + 30 * math.cos(a / 20 * math.pi), 3)] for a in range(40)]

    def cur(y, x, h):
        dy, dx = y - 60, x - 102
        r = math.hypot(dy, dx) or 1
        w = 0.35 * math.exp(-((r - 35) / 20) ** 2)
        return 0.1 + 0.05 * math.sin(h / 6) - w * dy / r, w * dx / r

    start, goal = [20.0, 10.0], [100.0, 190.0]
    pts = densify([start, [25.0, 60.0], [30.0, 100.0], [45.0, 145.0], [75.0, 170.0], goal], 6)
    t, wps = 0.0, []
    for i, p in enumerate(pts):
        if i:
            t += math.hypot(p[0] - pts[i - 1][0], p[1] - pts[i - 1][1]) * 1000 / 0.4
        if i % 4 == 0 or i == len(pts) - 1:
            u, v = cur(p[0], p[1], t / 3600)
            wps.append({'index': i, 'lat': p[0], 'lon': p[1], 'arrival': 't = %.2f h' % (t / 3600), 'elapsed': dhm(t),
                        'heading_deg': None, 'current': {'u': round(u, 3), 'v': round(v, 3), 'speed': round(math.hypot(u, v), 3),
                                                         'dir_deg': round((math.degrees(math.atan2(u, v)) + 360) % 360, 1)}})
    frames = [{'time': 't = %g h' % h, 'arrows': [[y, x, round(cur(y, x, h)[0], 3), round(cur(y, x, h)[1], 3)]
                                                  for y in range(0, 121, 8) for x in range(0, 201, 8)
                                                  if not any(inside([y, x], c) for c in cells)]} for h in (0, 48)]
    isochrones = [{'time': 't = %d h' % h, 'lines': [[[round(start[0] + 1.44 * h * math.sin(math.radians(a)), 3),
                                                     round(start[1] + 1.44 * h * math.cos(math.radians(a)), 3)] for a in range(0, 91, 3)]]}
                  for h in (24, 48, 72, 96)]
    return {'title': 'Planning frame sample (km)', 'geographic': False, 'units': 'km',
            'routes': [{'name': 'route', 'points': pts, 'waypoints': wps, 'travel_time': dhm(t)}],
            'start': start, 'goal': goal, 'goal_tolerance': 5, 'isochrones': isochrones, 'land': cells,
            'keep_off': [ring], 'forbidden': [],
            'currents': {'units': 'm/s', 'max_speed': 0.5, 'frames': frames},
            'bounds': [[0, 0], [120, 200]]}


if __name__ == '__main__':
    for name, data in (('sample_data.json', geographic()), ('sample_data_xy.json', planar())):
        with open(os.path.join(HERE, name), 'w', encoding='utf-8') as f:
            json.dump(data, f, ensure_ascii=False, separators=(',', ':'))
            f.write('\n')
        print(name, 'routes', [len(r['points']) for r in data['routes']], 'land', len(data['land']),
              'frames', len(data['currents']['frames']), 'isochrones', len(data['isochrones']))
