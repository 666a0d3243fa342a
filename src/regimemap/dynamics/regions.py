"""The regions of a refined outcome map as polygons, its boundaries as polylines (marching squares).

numpy only.  The input is the category of every node of the grid and the refined crossings of
:func:`regimemap.dynamics.boundaries.refine_crossings`; the output, :class:`MapGeometry`, is in
grid coordinates (``u`` the column index, ``v`` the row index, fractional between nodes), which
:meth:`MapGeometry.scaled` maps to any axes by linear interpolation between the nodes.

Each cell of the grid (four nodes) is cut along its boundaries:

* a cell without a crossing is one piece of its category;
* walking round a cell's edges, the crossings cut its perimeter into arcs of one category each.
  Two arcs: the chord between the two crossings divides the cell.  Four arcs of two alternating
  categories (a saddle): the category probed at the cell's centre joins its two arcs, and each
  arc of the other one is cut off by its chord.  One category on several arcs, every other on
  one (a thin band of it crossing an edge): that category runs through, and the other arcs are
  cut off by their chords.  Anything else (three or more categories meeting at a point): every
  crossing is joined to a junction at the centroid of the cell's crossings, and each arc with
  the junction is a piece.

The pieces of a category, counter-clockwise and sharing their vertices exactly, are merged by
cancelling the edges that two of them share; what is left chains into closed loops (outer
boundaries counter-clockwise, holes clockwise), with the vertices along grid lines between
collinear neighbours dropped.  The chords and the junction spokes between two categories chain
into the boundary polylines.
"""

from __future__ import annotations

from collections import defaultdict
from dataclasses import dataclass, field

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .boundaries import Crossings

__all__ = ["MapGeometry", "assemble"]

FloatArray = NDArray[np.float64]


@dataclass(frozen=True)
class MapGeometry:
    """Regions and boundaries of an outcome map.

    Attributes
    ----------
    regions : dict
        Category code -> its closed loops, each an (n, 2) array of (u, v) without the first
        point repeated; outer loops turn counter-clockwise in grid coordinates, holes clockwise.
    boundaries : list of (int, int, ndarray)
        ``(a, b, points)``: a polyline (n, 2) between categories a < b (closed ones end on
        their first point).
    """

    regions: dict[int, list[FloatArray]] = field(default_factory=dict)
    boundaries: list[tuple[int, int, FloatArray]] = field(default_factory=list)

    def scaled(self, x: ArrayLike, y: ArrayLike) -> MapGeometry:
        """The same geometry on axes whose nodes are at ``x`` (columns) and ``y`` (rows)."""
        xs = np.asarray(x, dtype=np.float64)
        ys = np.asarray(y, dtype=np.float64)

        def to(p: FloatArray) -> FloatArray:
            return np.column_stack([np.interp(p[:, 0], np.arange(xs.size), xs),
                                    np.interp(p[:, 1], np.arange(ys.size), ys)])

        return MapGeometry({c: [to(p) for p in loops] for c, loops in self.regions.items()},
                           [(a, b, to(p)) for a, b, p in self.boundaries])


class _Builder:
    """Points by id (the grid's nodes first), directed piece edges and boundary segments."""

    def __init__(self, nx: int, ny: int, c: Crossings):
        self.nx = nx
        uu, vv = np.meshgrid(np.arange(nx, dtype=np.float64), np.arange(ny, dtype=np.float64))
        cu = np.where(c.axis == 0, c.j + c.fraction, c.j).astype(np.float64)
        cv = np.where(c.axis == 0, c.i, c.i + c.fraction).astype(np.float64)
        self.u: list[float] = uu.ravel().tolist() + cu.tolist()
        self.v: list[float] = vv.ravel().tolist() + cv.tolist()
        self.edges: list[tuple[int, int, int]] = []  # (from, to, category)
        self.segments: list[tuple[int, int, int, int]] = []  # (p, q, a, b), a < b

    def point(self, u: float, v: float) -> int:
        self.u.append(u)
        self.v.append(v)
        return len(self.u) - 1

    def piece(self, ids: list[int], category: int) -> None:
        if len(set(ids)) < 3:  # no area: an arc of the edge without a node, cut off by its chord
            return
        for a, b in zip(ids, ids[1:] + ids[:1]):
            if a != b:
                self.edges.append((a, b, category))

    def segment(self, p: int, q: int, a: int, b: int) -> None:
        if p != q and a != b:
            self.segments.append((p, q, min(a, b), max(a, b)))


# A perimeter item: (point id, is a crossing, category after it, category before it) walking
# counter-clockwise round the cell.
_Item = tuple[int, bool, int, int]


def _perimeter(i: int, j: int, nx: int, cat: NDArray[np.int64],
               on_edge: dict[tuple[int, int, int], list[int]], before: list[int], after: list[int],
               n_nodes: int) -> list[_Item]:
    """The nodes and crossings round cell (i, j), counter-clockwise from node (i, j)."""
    out: list[_Item] = []

    def node(a: int, b: int) -> None:
        c = int(cat[a, b])
        out.append((a * nx + b, False, c, c))

    def edge(key: tuple[int, int, int], forward: bool) -> None:
        ids = on_edge.get(key, [])
        for pid in (ids if forward else ids[::-1]):
            k = pid - n_nodes
            out.append((pid, True, after[k], before[k]) if forward else (pid, True, before[k], after[k]))

    node(i, j)
    edge((0, i, j), True)
    node(i, j + 1)
    edge((1, i, j + 1), True)
    node(i + 1, j + 1)
    edge((0, i + 1, j), False)
    node(i + 1, j)
    edge((1, i, j), False)
    return out


def _cut(b: _Builder, seq: list[_Item], centre: int | None) -> None:
    """Cut a cell (its perimeter ``seq``) into pieces along its boundaries."""
    at = [t for t, item in enumerate(seq) if item[1]]
    if not at:
        b.piece([item[0] for item in seq], seq[0][2])
        return
    m = len(at)
    arcs: list[tuple[int, list[int], int]] = []  # (start crossing, nodes, category)
    for q in range(m):
        s, e = at[q], at[(q + 1) % m]
        inner = seq[s + 1:e] if e > s else seq[s + 1:] + seq[:e]
        arcs.append((seq[s][0], [item[0] for item in inner], seq[s][2]))
    count: dict[int, int] = defaultdict(int)
    for a in arcs:
        count[a[2]] += 1
    repeated = [c for c, n in count.items() if n > 1]
    joined: int | None = None
    if m == 2:
        joined = arcs[0][2]
    elif len(count) == 2 and centre in count:  # a saddle, resolved at its centre
        joined = centre
    elif len(repeated) == 1:  # one category on several arcs: it runs through, the others are cut off
        joined = repeated[0]
    if joined is not None:
        ring: list[int] = []
        for q, (start, nodes, c) in enumerate(arcs):
            end = arcs[(q + 1) % m][0]
            if c == joined:
                ring += [start, *nodes]
            else:
                ring.append(start)
                b.piece([start, *nodes, end], c)
                b.segment(end, start, c, joined)
        b.piece(ring, joined)
        return
    ju = float(np.mean([b.u[a[0]] for a in arcs]))
    jv = float(np.mean([b.v[a[0]] for a in arcs]))
    junction = b.point(ju, jv)
    for q, (start, nodes, c) in enumerate(arcs):
        end = arcs[(q + 1) % m][0]
        b.piece([start, *nodes, end, junction], c)
        b.segment(start, junction, arcs[q - 1][2], c)


def _uniform_edges(cat: NDArray[np.int64], mixed: NDArray[np.bool_]) -> NDArray[np.int64]:
    """Directed edges (from, to, category) of the cells with no crossing, counter-clockwise."""
    ny, nx = cat.shape
    i, j = np.nonzero(~mixed)
    n00 = i * nx + j
    n01, n11, n10 = n00 + 1, n00 + nx + 1, n00 + nx
    c = cat[i, j]
    src = np.concatenate([n00, n01, n11, n10])
    dst = np.concatenate([n01, n11, n10, n00])
    return np.column_stack([src, dst, np.tile(c, 4)]).astype(np.int64)


def _cancel(edges: NDArray[np.int64]) -> NDArray[np.int64]:
    """The directed edges left when each edge cancels one that runs back along it (same category)."""
    if edges.size == 0:
        return edges
    lo = np.minimum(edges[:, 0], edges[:, 1])
    hi = np.maximum(edges[:, 0], edges[:, 1])
    key, inverse = np.unique(np.column_stack([lo, hi, edges[:, 2]]), axis=0, return_inverse=True)
    net = np.zeros(len(key), dtype=np.int64)
    np.add.at(net, inverse.ravel(), np.where(edges[:, 0] == lo, 1, -1))
    keep = np.repeat(np.arange(len(key)), np.abs(net))
    forward = net[keep] > 0
    src = np.where(forward, key[keep, 0], key[keep, 1])
    dst = np.where(forward, key[keep, 1], key[keep, 0])
    return np.column_stack([src, dst, key[keep, 2]]).astype(np.int64)


def _loops(edges: NDArray[np.int64]) -> dict[int, list[list[int]]]:
    """Chain directed edges into closed loops of point ids, by category."""
    out: dict[int, list[list[int]]] = defaultdict(list)
    order = np.lexsort((edges[:, 1], edges[:, 0], edges[:, 2])) if edges.size else np.zeros(0, int)
    outgoing: dict[tuple[int, int], list[int]] = defaultdict(list)
    for k in order.tolist():
        outgoing[(int(edges[k, 2]), int(edges[k, 0]))].append(k)
    used = np.zeros(len(edges), dtype=bool)
    for k0 in order.tolist():
        if used[k0]:
            continue
        c = int(edges[k0, 2])
        loop = [int(edges[k0, 0])]
        used[k0] = True
        here = int(edges[k0, 1])
        while here != loop[0]:
            loop.append(here)
            nxt = next((k for k in outgoing[(c, here)] if not used[k]), None)
            if nxt is None:  # pragma: no cover - the pieces always close
                break
            used[nxt] = True
            here = int(edges[nxt, 1])
        out[c].append(loop)
    return out


def _simplify(loop: list[int], u: FloatArray, v: FloatArray) -> list[int]:
    """Drop the vertices between two neighbours on the same grid line (same u or same v).

    One pass is enough: neighbours dropped together lie on one line with theirs.
    """
    n = len(loop)
    if n <= 3:
        return loop
    keep = [p for t, p in enumerate(loop)
            if not (u[loop[t - 1]] == u[p] == u[loop[(t + 1) % n]]
                    or v[loop[t - 1]] == v[p] == v[loop[(t + 1) % n]])]
    return keep if len(keep) >= 3 else loop


def _polylines(segments: list[tuple[int, int, int, int]]) -> list[tuple[int, int, list[int]]]:
    """Chain the boundary segments of each pair of categories into polylines (ends first)."""
    by_pair: dict[tuple[int, int], list[tuple[int, int]]] = defaultdict(list)
    for p, q, a, b in segments:
        by_pair[(a, b)].append((p, q))
    out: list[tuple[int, int, list[int]]] = []
    for (a, b), segs in sorted(by_pair.items()):
        near: dict[int, list[int]] = defaultdict(list)
        for s, (p, q) in enumerate(segs):
            near[p].append(s)
            near[q].append(s)
        used = [False] * len(segs)
        ends = sorted(pt for pt, ss in near.items() if len(ss) % 2 == 1)
        starts = ends + sorted(near)
        for start in starts:
            while any(not used[s] for s in near[start]):
                line = [start]
                here = start
                while True:
                    nxt = next((s for s in near[here] if not used[s]), None)
                    if nxt is None:
                        break
                    used[nxt] = True
                    p, q = segs[nxt]
                    here = q if p == here else p
                    line.append(here)
                out.append((a, b, line))
    return out


def assemble(category: ArrayLike, crossings: Crossings) -> MapGeometry:
    """The regions (polygons) and boundaries (polylines) of a map in grid coordinates.

    Parameters
    ----------
    category : array_like of int, shape (ny, nx)
        The category of every node (ny, nx >= 2).
    crossings : Crossings
        Its refined crossings (every edge between two categories has at least one).

    Returns
    -------
    MapGeometry
    """
    cat = np.asarray(category).astype(np.int64)
    ny, nx = cat.shape
    if nx < 2 or ny < 2:
        raise ValueError("a map needs two nodes on each axis to have regions")
    n_nodes = nx * ny
    b = _Builder(nx, ny, crossings)
    on_edge: dict[tuple[int, int, int], list[int]] = defaultdict(list)
    for k, key in enumerate(zip(crossings.axis.tolist(), crossings.i.tolist(), crossings.j.tolist())):
        on_edge[key].append(n_nodes + k)  # sorted by fraction (refine_crossings sorts them)
    mixed = np.zeros((ny - 1, nx - 1), dtype=bool)
    for ax, i, j in on_edge:
        if ax == 0:
            mixed[max(i - 1, 0):min(i + 1, ny - 1), j] = True
        else:
            mixed[i, max(j - 1, 0):min(j + 1, nx - 1)] = True
    centres = {(int(i), int(j)): int(c) for i, j, c in
               zip(crossings.centre_i.tolist(), crossings.centre_j.tolist(), crossings.centre.tolist())}
    before, after = crossings.before.astype(int).tolist(), crossings.after.astype(int).tolist()
    for i, j in zip(*(a.tolist() for a in np.nonzero(mixed))):
        seq = _perimeter(i, j, nx, cat, on_edge, before, after, n_nodes)
        _cut(b, seq, centres.get((i, j)))
    edges = np.concatenate([_uniform_edges(cat, mixed),
                            np.asarray(b.edges, dtype=np.int64).reshape(-1, 3)])
    u, v = np.asarray(b.u), np.asarray(b.v)
    regions: dict[int, list[FloatArray]] = {}
    for c, loops in sorted(_loops(_cancel(edges)).items()):
        regions[c] = [np.column_stack([u[ids], v[ids]]) for ids in (_simplify(lp, u, v) for lp in loops)]
    lines = [(a, bb, np.column_stack([u[ids], v[ids]])) for a, bb, ids in _polylines(b.segments)]
    return MapGeometry(regions, lines)
