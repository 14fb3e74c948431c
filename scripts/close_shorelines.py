#!/usr/bin/env python3
"""Land polygons of a box from shorelines (GMT multi-segment text, as `gmt coast -M -W` writes it).

Shorelines that close on themselves inside the box are islands. A shoreline cut by the box is clipped to it, and
the pieces are closed along the box's edges: walking the box's boundary anticlockwise, land and water alternate at
each point where a shoreline meets it, so knowing whether the box's south-west corner is on land (`--corner-land`;
make_coastline.sh asks GMT) tells which stretches of the boundary belong to land. Each land polygon is a piece of
shoreline followed by the stretch of boundary (with the box's corners on it) up to the next piece, and so on round.

Usage: close_shorelines.py --corner-land yes|no -- LON_MIN/LON_MAX/LAT_MIN/LAT_MAX < segments.txt > land.geojson
Writes GeoJSON (one Polygon feature per land polygon, named "land N") and a summary on stderr.
"""
import argparse
import json
import sys

EPS = 1e-9


def read_segments(stream):
    """Segments of GMT multi-segment text: lists of (lon, lat)."""
    segments, cur = [], None
    for line in stream:
        line = line.strip()
        if not line or line.startswith("#"):
            continue
        if line.startswith(">"):
            cur = []
            segments.append(cur)
            continue
        if cur is None:
            cur = []
            segments.append(cur)
        x, y = map(float, line.split()[:2])
        cur.append((x, y))
    return [s for s in segments if len(s) >= 2]


def unwrap(segments, box):
    """Longitudes brought within 180 degrees of the box's centre: GMT writes lon -179 for 181 on a box across 180."""
    c = 0.5 * (box[0] + box[1])
    return [[(c + (x - c + 180.0) % 360.0 - 180.0, y) for x, y in s] for s in segments]


def join_segments(segments):
    """Shorelines joined end to end: GMT's `coast -M -W` writes a shoreline cut into pieces at the edges of its
    bins (every degree or two), each piece starting where the one before it ends. Pieces are joined where an end of
    one is an end of another (reversing a piece when needed); closed shorelines are left as they are."""
    def key(p):
        return (round(p[0], 7), round(p[1], 7))

    done, open_ = [], []
    for s in segments:
        (done if len(s) >= 4 and key(s[0]) == key(s[-1]) else open_).append(list(s))
    ends = {}  # end point -> indices of the open pieces with an end there
    for k, s in enumerate(open_):
        ends.setdefault(key(s[0]), []).append(k)
        ends.setdefault(key(s[-1]), []).append(k)
    used = [False] * len(open_)

    def take(point, exclude):
        for k in ends.get(key(point), []):
            if not used[k] and k != exclude:
                return k
        return None

    for k in range(len(open_)):
        if used[k]:
            continue
        used[k] = True
        line = list(open_[k])
        for forward in (True, False):
            while key(line[0]) != key(line[-1]):
                tip = line[-1] if forward else line[0]
                j = take(tip, k)
                if j is None:
                    break
                used[j] = True
                s = open_[j]
                if forward:
                    line.extend((s if key(s[0]) == key(tip) else s[::-1])[1:])
                else:
                    line[:0] = (s if key(s[-1]) == key(tip) else s[::-1])[:-1]
        if len(line) >= 4 and key(line[0]) == key(line[-1]):
            line[-1] = line[0]
        done.append(line)
    return done


def inside(p, box):
    x0, x1, y0, y1 = box
    return x0 - EPS <= p[0] <= x1 + EPS and y0 - EPS <= p[1] <= y1 + EPS


def clip_segment(a, b, box):
    """Liang-Barsky: the part of segment a-b inside the box as (t0, t1), or None."""
    x0, x1, y0, y1 = box
    t0, t1 = 0.0, 1.0
    dx, dy = b[0] - a[0], b[1] - a[1]
    for p, q in ((-dx, a[0] - x0), (dx, x1 - a[0]), (-dy, a[1] - y0), (dy, y1 - a[1])):
        if p == 0:
            if q < 0:
                return None
        else:
            r = q / p
            if p < 0:
                t0 = max(t0, r)
            else:
                t1 = min(t1, r)
    if t0 > t1:
        return None
    return t0, t1


def at(a, b, t):
    return (a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]))


def clip_line(points, box):
    """The pieces of a polyline inside the box (lists of points)."""
    pieces, cur = [], []
    for a, b in zip(points, points[1:]):
        c = clip_segment(a, b, box)
        if c is None:
            if cur:
                pieces.append(cur)
                cur = []
            continue
        p, q = at(a, b, c[0]), at(a, b, c[1])
        if cur and (abs(cur[-1][0] - p[0]) > EPS or abs(cur[-1][1] - p[1]) > EPS):
            pieces.append(cur)
            cur = []
        if not cur:
            cur = [p]
        cur.append(q)
        if c[1] < 1.0:  # leaves the box
            pieces.append(cur)
            cur = []
    if cur:
        pieces.append(cur)
    return [p for p in pieces if len(p) >= 2]


def split_on_edges(points, box):
    """A shoreline cut where it runs along the box's boundary. GMT clips shorelines to the region itself and joins
    the part outside by a walk along the region's edge (sometimes closing a shoreline through a corner): those
    stretches are the box's boundary, not coast, and the closing below walks the boundary itself."""
    x0, x1, y0, y1 = box
    tol = 1e-7 * max(x1 - x0, y1 - y0)

    def same_edge(a, b):
        return ((abs(a[0] - x0) <= tol and abs(b[0] - x0) <= tol) or (abs(a[0] - x1) <= tol and abs(b[0] - x1) <= tol)
                or (abs(a[1] - y0) <= tol and abs(b[1] - y0) <= tol)
                or (abs(a[1] - y1) <= tol and abs(b[1] - y1) <= tol))

    parts, cur = [], [points[0]]
    for a, b in zip(points, points[1:]):
        if same_edge(a, b):
            if len(cur) >= 2:
                parts.append(cur)
            cur = [b]
        else:
            cur.append(b)
    if len(cur) >= 2:
        parts.append(cur)
    if len(parts) >= 2 and parts[0][0] == parts[-1][-1] and points[0] == points[-1]:
        parts[0] = parts.pop()[:-1] + parts[0]  # a closed shoreline cut once: one piece
    return parts


def perimeter_position(p, box):
    """Anticlockwise distance along the box's boundary from its south-west corner, or None off the boundary."""
    x0, x1, y0, y1 = box
    w, h = x1 - x0, y1 - y0
    tol = 1e-7 * max(w, h)
    if abs(p[1] - y0) <= tol:
        return p[0] - x0
    if abs(p[0] - x1) <= tol:
        return w + p[1] - y0
    if abs(p[1] - y1) <= tol:
        return w + h + x1 - p[0]
    if abs(p[0] - x0) <= tol:
        return (2 * w + h + y1 - p[1]) % (2 * (w + h))
    return None


def corners_between(t_from, t_to, box):
    """The box's corners passed going anticlockwise from perimeter position t_from to t_to."""
    x0, x1, y0, y1 = box
    w, h = x1 - x0, y1 - y0
    perim = 2 * (w + h)
    corners = [(w, (x1, y0)), (w + h, (x1, y1)), (2 * w + h, (x0, y1)), (perim, (x0, y0))]
    span = (t_to - t_from) % perim
    out = []
    for k in range(2):  # the corners of this turn and the next, in order
        for tc, c in corners:
            d = tc + k * perim - t_from
            if 0 < d < span:
                out.append((d, c))
    return [c for _, c in sorted(out)]


def close_shorelines(segments, box, corner_land):
    """Land polygons (closed rings of (lon, lat)) of the box; and messages on what was left out."""
    rings, pieces, notes = [], [], []
    for s in [part for seg in segments for part in split_on_edges(seg, box)]:
        closed = len(s) >= 4 and s[0] == s[-1]
        if closed and all(inside(p, box) for p in s):
            rings.append(list(s))
            continue
        for piece in clip_line(s, box):
            ta, tb = perimeter_position(piece[0], box), perimeter_position(piece[-1], box)
            if ta is None or tb is None:
                notes.append("a shoreline from %s to %s ends inside the box: left out" % (piece[0], piece[-1]))
                continue
            if abs(ta - tb) <= 1e-12 and len(piece) <= 2:
                continue  # a touch of the boundary
            pieces.append((piece, ta, tb))
    x0, x1, y0, y1 = box
    perim = 2 * ((x1 - x0) + (y1 - y0))
    if not pieces:
        if corner_land:
            rings.append([(x0, y0), (x1, y0), (x1, y1), (x0, y1), (x0, y0)])
        return rings, notes
    # land after each endpoint along the boundary: flips at every endpoint, starting from the corner's state
    ends = sorted({t for _, ta, tb in pieces for t in (ta, tb)})
    land_after, state = {}, corner_land
    for t in ends:
        state = not state
        land_after[t] = state
    if state != corner_land:
        notes.append("the shorelines meet the box's boundary an odd number of times: the result may be wrong")
    # orient each piece so that it ends where land follows along the boundary (land on its left)
    starts = {}
    oriented = []
    for piece, ta, tb in pieces:
        if land_after[tb] and not land_after[ta]:
            oriented.append((piece, ta, tb))
        elif land_after[ta] and not land_after[tb]:
            oriented.append((piece[::-1], tb, ta))
        else:
            notes.append("a shoreline from %s to %s has land on both sides: left out" % (piece[0], piece[-1]))
            continue
        starts[oriented[-1][1]] = len(oriented) - 1
    used = [False] * len(oriented)
    for k in range(len(oriented)):
        if used[k]:
            continue
        ring, j = [], k
        while not used[j]:
            used[j] = True
            piece, ta, tb = oriented[j]
            ring.extend(piece)
            nxt = min((t for t in starts if (t - tb) % perim > 1e-12), key=lambda t: (t - tb) % perim, default=None)
            if nxt is None:
                break
            ring.extend(corners_between(tb, nxt, box))
            j = starts[nxt]
        if ring[0] != ring[-1]:
            ring.append(ring[0])
        if len(ring) >= 4:
            rings.append(ring)
    return rings, notes


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("region", help="LON_MIN/LON_MAX/LAT_MIN/LAT_MAX")
    ap.add_argument("--corner-land", choices=["yes", "no"], required=True,
                    help="whether the box's south-west corner is on land")
    args = ap.parse_args()
    try:
        box = tuple(float(v) for v in args.region.split("/"))
        if len(box) != 4 or not (box[0] < box[1] and box[2] < box[3]):
            raise ValueError
    except ValueError:
        print("close_shorelines: region '%s': expected LON_MIN/LON_MAX/LAT_MIN/LAT_MAX with MIN < MAX"
              % args.region, file=sys.stderr)
        return 2
    segments = join_segments(unwrap(read_segments(sys.stdin), box))
    rings, notes = close_shorelines(segments, box, args.corner_land == "yes")
    features = [{"type": "Feature", "properties": {"name": "land %d" % (k + 1), "kind": "land"},
                 "geometry": {"type": "Polygon",
                              "coordinates": [[[round(x, 6), round(y, 6)] for x, y in r]]}}
                for k, r in enumerate(rings)]
    json.dump({"type": "FeatureCollection", "features": features}, sys.stdout)
    sys.stdout.write("\n")
    for n in notes:
        print("close_shorelines: " + n, file=sys.stderr)
    print("close_shorelines: %d land polygons" % len(rings), file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
