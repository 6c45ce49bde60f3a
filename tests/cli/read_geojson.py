#!/usr/bin/env python3
"""Reads a GeoJSON footprint back, independently of umbra (CTest footprint.geojson_*).

Usage: read_geojson.py FOOTPRINT.geojson FOOTPRINT.csv SCENE.json [--horizontal NAME:POLYGON,...]

A series (`umbra footprint --sun-times`) is read the same way, each
feature's "time" standing for its light and the per-step CSV for the
per-light one.

- GDAL/OGR (Debian's python3-gdal) opens the file with its GeoJSON driver:
  the layer must be geographic WGS84, every feature a valid (GEOS) 3D
  polygon without holes; the raw JSON must be RFC 7946's shape: a
  FeatureCollection without "crs", closed rings, longitudes and latitudes
  in range, the exterior ring counter-clockwise (§3.1.6).
- Each ring is taken back to the site's east-north-up frame with the
  textbook geodetic -> geocentric -> ENU formulas (no PROJ, unlike umbra's
  writer), at the site read from the scene file; its shoelace area in
  (east, north) must equal the feature's area_m2 within a relative 1e-6.
  Why that bound holds with room to spare: umbra's positions are within
  1e-11 degrees (a micrometre) of the ellipsoid's exact answer
  (GeodeticFrame tests) and this script's double arithmetic on geocentric
  coordinates of 6.4e6 m adds about 1e-8 m; a vertex error d moves an area
  by at most d times the perimeter P, so the relative error is below
  1e-6 m * P / A, which the script checks is under 1e-6 for every region
  (a sliver too thin for the bound would be reported, not excused).
- The regions of each receiver add up to its area in the --csv file
  (relative 1e-6), and the receivers written are exactly the scene's
  horizontal ones named by --horizontal (for every light with a footprint).
Prints a one-line summary; exit 1 with the reasons on any failure.
"""
import argparse
import csv
import json
import math
import sys
from collections import defaultdict

from osgeo import ogr, osr  # Debian's python3-gdal

ogr.UseExceptions()
osr.UseExceptions()

A = 6378137.0
F = 1 / 298.257223563
E2 = F * (2 - F)
POSITION_ERROR_M = 1e-6  # see the docstring

failures = []


def fail(msg):
    failures.append(msg)


def geocentric(lon, lat, h):
    phi, lam = math.radians(lat), math.radians(lon)
    n = A / math.sqrt(1 - E2 * math.sin(phi) ** 2)
    return ((n + h) * math.cos(phi) * math.cos(lam), (n + h) * math.cos(phi) * math.sin(lam),
            (n * (1 - E2) + h) * math.sin(phi))


class Enu:
    """East, north, up metres at a site (the ellipsoid's tangent frame)."""

    def __init__(self, lon0, lat0, h0):
        self.origin = geocentric(lon0, lat0, h0)
        phi, lam = math.radians(lat0), math.radians(lon0)
        sp, cp, sl, cl = math.sin(phi), math.cos(phi), math.sin(lam), math.cos(lam)
        self.east = (-sl, cl, 0.0)
        self.north = (-sp * cl, -sp * sl, cp)
        self.up = (cp * cl, cp * sl, sp)

    def __call__(self, lon, lat, h):
        d = [a - b for a, b in zip(geocentric(lon, lat, h), self.origin)]
        return tuple(sum(x * y for x, y in zip(d, axis)) for axis in (self.east, self.north, self.up))


def shoelace(points):
    """Twice the signed area and the perimeter of a closed ring of (e, n)."""
    twice = perimeter = 0.0
    for (x0, y0), (x1, y1) in zip(points, points[1:]):
        twice += x0 * y1 - x1 * y0
        perimeter += math.hypot(x1 - x0, y1 - y0)
    return twice, perimeter


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("geojson")
    ap.add_argument("csv")
    ap.add_argument("scene")
    ap.add_argument("--horizontal",
                    help="the scene's horizontal receivers as model_name:polygon,... "
                    "(checked to be exactly those written, when given)")
    args = ap.parse_args()

    site = json.load(open(args.scene))["site"]
    enu = Enu(site["longitude"], site["latitude"], site.get("elevation_m", 0))

    # OGR: the driver's view of the file.
    ds = ogr.Open(args.geojson)
    if ds is None or ds.GetDriver().GetName() != "GeoJSON":
        sys.exit(f"{args.geojson}: OGR's GeoJSON driver cannot open it")
    layer = ds.GetLayer(0)
    srs = layer.GetSpatialRef()
    # RFC 7946 files are WGS84, EPSG:4979 when positions carry a height
    # (4326 without), longitude first in the data (axis mapping [2, 1, ...]).
    if (srs is None or not srs.IsGeographic() or srs.GetAttrValue("DATUM") != "WGS_1984"
            or srs.GetAuthorityCode(None) not in ("4326", "4979")
            or srs.GetDataAxisToSRSAxisMapping()[:2] != [2, 1]):
        fail(f"layer CRS is not WGS84 longitude, latitude: {srs.ExportToProj4() if srs else None}")
    ogr_features = list(layer)
    for feature in ogr_features:
        g = feature.GetGeometryRef()
        if g.GetGeometryType() != ogr.wkbPolygon25D:
            fail(f"feature {feature.GetFID()}: {g.GetGeometryName()} (3D), not a 3D polygon")
        elif g.GetGeometryCount() != 1:
            fail(f"feature {feature.GetFID()}: {g.GetGeometryCount()} rings, expected 1")
        if not g.IsValid():
            fail(f"feature {feature.GetFID()}: not a valid polygon (GEOS)")

    # The raw JSON: RFC 7946's shape and the areas.
    doc = json.load(open(args.geojson))
    if doc.get("type") != "FeatureCollection" or "crs" in doc:
        fail("not a FeatureCollection without crs")
    features = doc["features"]
    if len(features) != len(ogr_features):
        fail(f"OGR read {len(ogr_features)} features, the JSON holds {len(features)}")
    sums = defaultdict(float)
    worst_rel = worst_bound = 0.0
    for i, f in enumerate(features):
        p, geometry = f["properties"], f["geometry"]
        name = f"feature {i} (light {p['light']}, {p['model_name']} polygon {p['polygon']})"
        if geometry["type"] != "Polygon" or len(geometry["coordinates"]) != 1:
            fail(f"{name}: not a one-ring Polygon")
            continue
        if p["class"] not in ("lit", "shadowed"):
            fail(f"{name}: class {p['class']!r}")
        ring = geometry["coordinates"][0]
        if len(ring) < 4 or ring[0] != ring[-1]:
            fail(f"{name}: ring not closed ({len(ring)} positions)")
            continue
        if any(len(q) != 3 or not (-180 <= q[0] <= 180 and -90 <= q[1] <= 90) for q in ring):
            fail(f"{name}: a position out of range or not [lon, lat, h]")
        local = [enu(*q)[:2] for q in ring]
        twice, perimeter = shoelace(local)
        area = twice / 2
        if area <= 0:
            fail(f"{name}: exterior ring clockwise (signed area {area})")
            continue
        rel = abs(area - p["area_m2"]) / p["area_m2"]
        bound = POSITION_ERROR_M * perimeter / p["area_m2"]
        worst_rel, worst_bound = max(worst_rel, rel), max(worst_bound, bound)
        # The positions' error bounds the area's; a region small against its
        # perimeter (a shadow's sliver on a roof) gets that bound, others 1e-6.
        if rel >= max(1e-6, bound):
            fail(f"{name}: area {area} in the site's frame, area_m2 {p['area_m2']} (rel {rel:.3g},"
                 f" bound {max(1e-6, bound):.3g})")
        sums[(p.get("time", p["light"]), p["model_name"], p["polygon"])] += area

    # The CSV: every written receiver whole; exactly the horizontal ones.
    rows = list(csv.DictReader(open(args.csv)))
    def step(r):  # a light's index, or a series step's time
        return r["time"] if "time" in r else int(r["light"])
    if args.horizontal:
        expected = {(m, int(k)) for m, k in (x.split(":") for x in args.horizontal.split(","))}
        lights = {step(r) for r in rows}
        wanted = {(light, m, k) for light in lights for (m, k) in expected}
        if set(sums) != wanted:
            fail(f"receivers written {sorted(set(sums))}, expected {sorted(wanted)}")
    elif not sums:
        fail("no feature at all")
    for r in rows:
        key = (step(r), r["model_name"], int(r["polygon"]))
        if key in sums:
            area = float(r["area"])
            if abs(sums[key] - area) >= 1e-6 * area:
                fail(f"receiver {key}: regions add up to {sums[key]}, the CSV says {area}")

    for msg in failures[:20]:
        print(msg)
    if failures:
        print(f"read_geojson: FAILED: {len(failures)} failures")
        return 1
    print(f"read_geojson: {len(features)} features on {len(sums)} receivers, "
          f"worst relative area error {worst_rel:.2e} (bound {worst_bound:.2e})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
