"""The charts' README: one paragraph per chart that reads it for a learner, with this run's figures.

Where it sits: written last by :mod:`game.bench.run`, next to the charts and CSVs, so the
numbers in the prose are always the numbers in the pictures.
"""

from __future__ import annotations

from statistics import median

from game.bench import (
    broad,
    caching,
    game_step,
    grid_cells,
    narrow,
    peer,
    targets,
    tunnelling,
    walls,
)
from game.bench.intervals import median_interval, paired_ratio
from game.bench.records import Row, markdown_table, values
from game.bench.sizes import Sizes
from game.bench.targets import Target
from game.collision import methods


def _cost(rows: list[Row], method: str, family: str) -> float:
    return median(values(rows, method=method, parameter=family, unit="ns/test"))


def _wrong(rows: list[Row], method: str, family: str) -> float:
    return sum(values(rows, method=method, parameter=family, unit="% false hits")
               + values(rows, method=method, parameter=family, unit="% missed hits"))


def narrow_text(rows: list[Row]) -> str:
    lines = []
    for family in narrow.FAMILIES:
        exact = sorted((_cost(rows, m.name, family), m.name) for m in narrow.METHODS
                       if _wrong(rows, m.name, family) == 0)
        rect = narrow.METHODS[0].name
        best = (f"the cheapest exact one is {exact[0][1]} at {exact[0][0]:,.0f} ns"
                if exact else "no method here is exact on every pair")
        lines.append(f"*{family}*: {rect} takes {_cost(rows, rect, family):,.0f} ns and is "
                     f"wrong on {_wrong(rows, rect, family):.1f} % of pairs; {best}.")
    return (
        "**Narrow phase** (`narrow_phase.png`). One panel per shape family. Each point is one "
        "method: across, the time for one overlap test (log scale, ns); up, the share of "
        "random pairs it answers wrongly against the exact oracle (the label splits it into "
        "% false hits / % missed hits). Pairs are placed within reach of each other, so about "
        "half touch: these are the hard cases. The dashed line is the Pareto front; a method "
        "off it is beaten on both counts by one on it. Notice how cheap `Rect.colliderect` is "
        "(one call into C) and that it is still wrong on boxes, because a Rect holds whole "
        "pixels; that bounding boxes and circles only ever err towards a hit; that masks miss "
        "by up to half a pixel; and that the pre-check costs more than the test it guards. "
        + " ".join(lines))


def tunnelling_text(rows: list[Row], flights: int) -> str:
    def missed(method: str, speed: str) -> float:
        return values(rows, method=method, parameter=speed, unit="% missed")[0]

    def late(method: str, speed: str) -> float:
        return values(rows, method=method, parameter=speed, unit="ticks late (mean)")[0]

    top = max((r.parameter for r in rows if r.method == tunnelling.SWEPT), key=float)
    clamp = tunnelling.METHODS[4].name
    threshold = (tunnelling.WALL.w + tunnelling.BODY_W_PX) / tunnelling.TILE_PX
    return (
        "**Tunnelling** (`tunnelling.png`). A 12 px body flies head-on at a 16 px wall, "
        f"{flights:,} flights per speed with random start phases; across, the speed in tiles per "
        "tick. Left: the share of flights that never registered a contact. The discrete "
        f"check is safe up to T + S = 28 px ({threshold:g} tiles) per tick, then follows the "
        f"formula 1 - (T + S) / v (dashed): at {top} tiles per tick it missed "
        f"{missed(tunnelling.DISCRETE, top):.1f} % (formula "
        f"{missed(tunnelling.ANALYTIC, top):.1f} %, worst gap "
        f"{tunnelling.worst_gap(rows, tunnelling.DISCRETE, tunnelling.ANALYTIC):.2f} "
        "percentage points). Two sub-steps only push the problem to twice the speed "
        f"({missed('sub-steps x2', top):.1f} % missed at {top}); `steps_needed`, the clamp "
        f"and swept AABB miss nothing. Middle: how deep inside the wall the body was when "
        "the contact was noticed: what the resolution must undo; swept is always 0. Right: "
        f"how late the contact was noticed. Clamping to 12 px per tick arrives "
        f"{late(clamp, top):.1f} ticks late at {top} tiles per tick: it hides tunnelling by "
        "slowing everything down. Swept AABB misses nothing, is never inside the wall and "
        "never late: that is why the game sweeps every move.")


def broad_text(rows: list[Row]) -> str:
    crossover = broad.crossover(rows, broad.GRID, broad.BRUTE)
    c_loop = broad.crossover(rows, broad.GRID, broad.COLLIDELISTALL)
    c_group = broad.crossover(rows, broad.GRID, broad.GROUPCOLLIDE)
    differ = sum(values(rows, unit="pairs unlike the grid's"))
    same = ("All methods returned the same pair set at every N (checked; `pairs unlike the "
            "grid's` in the CSV is 0 throughout)." if differ == 0 else
            f"WARNING: some methods' pair sets differ from the grid's ({differ:g} pairs in "
            "all; see `pairs unlike the grid's` in the CSV): a broad phase has a bug.")
    at = {m: broad.medians(rows, m) for m in broad.METHODS}

    def afford(method: str, budget_ms: float) -> str:
        fits = [n for n, ms in at[method].items() if ms <= budget_ms]
        return f"{max(fits):,}" if fits else "none"

    n = broad.verdict_n(rows)
    mid = (f" At N = {n:,} (timed in more rounds, for the targets) one frame costs "
           f"{at[broad.GROUPCOLLIDE][n]:.1f} ms with groupcollide(G, G), "
           f"{at[broad.COLLIDELISTALL][n]:.2f} ms with collidelistall and "
           f"{at[broad.GRID][n]:.2f} ms with the grid: the grid is "
           f"{broad.faster_than(rows, broad.GROUPCOLLIDE, n).text()}x and "
           f"{broad.faster_than(rows, broad.COLLIDELISTALL, n).text()}x faster "
           "[95 % intervals]." if n is not None else "")
    return (
        "**Broad phase** (`broad_phase.png`). Across, N moving boxes in the scene; up, the "
        "time of one frame (every box moved 0 to 2 px, the method brought up to date, every "
        "overlapping pair found), both on log scales, so N² methods are steep lines and the "
        "structures shallow ones. " + same + " The dotted vertical line is the "
        f"crossover: the grid beats pure-Python brute force from N = {crossover} on. It "
        f"beats `groupcollide(G, G)` from N = {c_group}, and `Rect.collidelistall`, brute "
        f"force with its inner loop in C, only from N = {c_loop}: a C loop is a hard "
        "baseline. Within the 2 ms line, "
        f"groupcollide(G, G) handles N = {afford(broad.GROUPCOLLIDE, 2)}, the grid N = "
        f"{afford(broad.GRID, 2)}; within a whole 16.7 ms frame, groupcollide N = "
        f"{afford(broad.GROUPCOLLIDE, 16.7)}, the grid N = {afford(broad.GRID, 16.7)}.{mid} "
        "The quadtree pays for its tree on every move; sort and sweep is simple and "
        "competitive while boxes are spread along x.")


def cells_text(rows: list[Row]) -> str:
    factors = sorted({r.parameter for r in rows}, key=float)
    spread = ", ".join(f"{f}x: {median(values(rows, parameter=f)):.2f} ms" for f in factors)
    best = grid_cells.fastest(rows)
    return (
        f"**Grid cell size** (`grid_cells.png`). The same grid at N = {rows[0].method.split()[-1]}"
        f" with cells from {factors[0]} to {factors[-1]} typical body sizes (16 px) across: "
        f"{spread}. Cells near the body size file each box under several cells; big cells "
        f"hold crowds. The smallest factor within {grid_cells.NEAR_FASTEST:.0%} of the "
        f"fastest was {best}x; the game uses `game.collision.methods.GRID_CELL_SIZE_FACTOR`.")


def walls_text(rows: list[Row]) -> str:
    maps = sorted({r.parameter for r in rows if r.unit == "µs/query"}, key=walls.tiles_of)
    small, big = maps[0], maps[-1]

    def cost(method: str, wall_map: str) -> float:
        return median(values(rows, method=method, parameter=wall_map, unit="µs/query"))

    wins = walls.lookup_wins_from(rows)
    return (
        "**Walls** (`walls.png`). Across, the map size in tiles (the first screens of "
        "First Steps repeated to fill it; the labels give the number of wall rectangles); "
        "up, the time for one body's query, both on log scales. The tile-grid lookup only "
        "visits the cells "
        f"under the body: {cost(walls.LOOKUP, small):.1f} µs on {small} and "
        f"{cost(walls.LOOKUP, big):.1f} µs on {big}, flat. `spritecollide` over every wall "
        f"sprite grows with the walls, from {cost(walls.SPRITES, small):.1f} µs to "
        f"{cost(walls.SPRITES, big):,.0f} µs; `collidelistall` runs the same scan in C, "
        f"{cost(walls.RECTS, small):.1f} to {cost(walls.RECTS, big):,.0f} µs: cheaper per "
        "wall, still proportional to the walls, and "
        + (f"the lookup beats it from the {wins} map on "
           f"({walls.tiles_of(wins):,} tiles: `TILE_LOOKUP_FROM_TILES`)."
           if wins else "the lookup never beats it here.")
        + " All three find the same walls.")


def caching_text(rows: list[Row]) -> str:
    return (
        "**The caching myth** (`caching.png`, `caching.csv`). Reading a body's `obj.rect` "
        "hands back the Rect it last derived from its float box (a property that works it "
        "out again only when the box or the picture has changed); `obj.rect.copy()` and "
        "`Rect(obj.rect)` build a new Rect on top of that, every time. The loop over the "
        "bodies is timed alone too, so the net column is the access itself, and the last "
        "column what a copy costs on top of the read (a difference in ns, not a ratio). "
        "Copying is the expensive way to \"cache\" a rect, and the copy is stale as soon "
        "as the body moves. Medians of interleaved rounds [95 % intervals].\n\n"
        + caching.markdown(rows))


def game_text(rows: list[Row]) -> str:
    played = game_step.played_line(rows)[0]
    return (
        f"**The game's step** (`game_step.png`). Left: {played} played to its exit by its "
        "winning script, the CPU time of every tick in ms, median over the plays; the "
        "dotted line is the 95th percentile of that line, "
        f"{game_step.p95_ms(rows):.3f} ms, and the dashed one the 2 ms share of a frame. "
        "Where the line steps down, a body has left the level (an enemy stomped): the work "
        "follows the bodies. Middle: the whole `World.step` of a 40 x 12 arena and of the "
        f"same arena in a map {game_step.WIDTH_FACTOR}x wider, same bodies and inputs: "
        f"{game_step.ratio(rows, game_step.WIDE, game_step.NARROW).text()}x the time. Right: "
        f"the wide arena with {game_step.MANY_PLATFORMS} moving platforms against "
        f"{game_step.FEW_PLATFORMS}, all far from the bodies: "
        f"{game_step.ratio(rows, game_step.MANY, game_step.FEW).text()}x the time "
        "[95 % intervals over the rounds].")


def peer_text(rows: list[Row]) -> str:
    def us(method: str) -> str:
        return median_interval(peer.per_update(rows, method)).text()

    moves = peer.figure_of(rows, "The Summit", "recorded moves")
    walls_n = peer.figure_of(rows, "The Summit", "solid tiles")
    flights = peer.FLIGHTS_PER_SPEED * len(peer.SPEEDS_PX)
    common = (
        f"**The peer** (`peer.png`). The same {walls_n:.0f} solid tiles of The Summit and the "
        f"same {moves:.0f} recorded moves of its player, made by each method from the same "
        f"boxes. Per update: the plain-float sweep {us(peer.PLAIN)} µs, `move_x` + `move_y` "
        f"{us(peer.GAME)} µs, the game's whole `World.step` {us(peer.STEP)} µs per body, the "
        f"`spritecollide` tutorial loop {us(peer.TUTORIAL)} µs"
        f" (medians [95 % intervals]). The tutorial loop tunnelled "
        f"{peer.tunnelled(rows, peer.TUTORIAL)} of {flights} flights at 8 to 64 px per tick "
        f"and jitters {peer.figure_of(rows, peer.TUTORIAL, 'px jitter at rest'):.2f} px at "
        "rest; the game's moves tunnelled "
        f"{peer.tunnelled(rows, peer.GAME)}, stop flush and never jitter.")
    if peer.skipped(rows):
        return common + (" Arcade was not installed, so its engine was skipped "
                         "(`pip install -e '.[peers]'` adds it).")
    ratio = paired_ratio(peer.per_update(rows, peer.ARCADE), peer.per_update(rows, peer.GAME))
    return common + (
        f" Arcade's `PhysicsEnginePlatformer.update` took {us(peer.ARCADE)} µs, "
        f"{ratio.text()}x as long as `move_x` + `move_y`; it ended "
        f"{peer.figure_of(rows, peer.ARCADE, peer.SAME):.0f} of the {moves:.0f} moves where "
        "the game does (within 0.01 px; it rounds its y to 1/100 px and lands in quarter "
        f"pixels), tunnelled {peer.tunnelled(rows, peer.ARCADE)} of {flights} flights, and "
        "stopped on average "
        f"{peer.figure_of(rows, peer.ARCADE, 'px short of flush (mean)'):.2f} px short of the "
        "face it was blocked by (it backs off by whole pixels).")


def choices(results: dict[str, list[Row]]) -> list[tuple[str, str, str]]:
    """The thresholds of :mod:`game.collision.methods`: name, value in the code, value this run
    found."""
    measured_n = broad.crossover(results[broad.CHART], broad.GRID, broad.BRUTE)
    best = grid_cells.fastest(results[grid_cells.CHART])
    wins = walls.lookup_wins_from(results[walls.CHART])
    return [("BROAD_PHASE_CROSSOVER_N", f"{methods.BROAD_PHASE_CROSSOVER_N}", f"{measured_n}"),
            ("GRID_CELL_SIZE_FACTOR", f"{methods.GRID_CELL_SIZE_FACTOR:g}", best),
            ("TILE_LOOKUP_FROM_TILES", f"{methods.TILE_LOOKUP_FROM_TILES}",
             f"{walls.tiles_of(wins) if wins else None}")]


def methods_text(results: dict[str, list[Row]]) -> str:
    rows = [[name, in_code, measured, where] for (name, in_code, measured), where in zip(
        choices(results), ["the crossover on `broad_phase.png`",
                           "the smallest factor within 5 % of the fastest on `grid_cells.png`",
                           "where the lookup overtakes `collidelistall` on `walls.png`"],
        strict=True)]
    return markdown_table(["threshold in game/collision/methods.py", "in the code", "this run",
                           "from"], rows)


def text(results: dict[str, list[Row]], checked: list[Target], sizes: Sizes,
         footnote: str) -> str:
    command = "python -m game.bench" + ("" if sizes.name == "full" else f" --{sizes.name}")
    return "\n\n".join([
        "# Benchmark charts",
        f"Written by `{command}` ({sizes.name} run) together with the charts and "
        "the CSVs in this folder; every figure below is a median of interleaved rounds in "
        "those CSVs (long format: chart, method, parameter, round, value, unit). Measured on: "
        f"{footnote}. Absolute times depend on the machine; the ratios travel better.",
        "## Targets\n\nEach ratio is a median of at least 30 interleaved rounds with its "
        "bootstrap 95 % interval in brackets; a target passes only when the whole interval "
        "clears its limit (`targets.png` draws them).\n\n" + targets.markdown(checked)
        + f"\n\n{sum(t.passed for t in checked)} of {len(checked)} targets met"
        + (f", {sum(bool(t.skipped) for t in checked)} skipped."
           if any(t.skipped for t in checked) else "."),
        "## The game's choices\n\nThe scene thresholds in `game/collision/methods.py` are set "
        "from, and "
        "cite, the committed run of this bench. A new run that disagrees is a reason to look "
        "again rather than to edit them blindly: where two lines run close, a crossover moves "
        "with noise.\n\n" + methods_text(results),
        "## Reading the charts",
        peer_text(results[peer.CHART]),
        narrow_text(results[narrow.CHART]),
        tunnelling_text(results[tunnelling.CHART], sizes.tunnel_flights),
        broad_text(results[broad.CHART]),
        cells_text(results[grid_cells.CHART]),
        walls_text(results[walls.CHART]),
        caching_text(results[caching.CHART]),
        game_text(results[game_step.CHART]),
    ]) + "\n"
