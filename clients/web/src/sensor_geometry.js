// Where each sensor set's points are, in metres, for drawing them: from the result (a work
// plane's `grid`, or a set's `points` where the service gives them) or else from the scene this
// viewer submitted (a `grid` expanded row-major, u fastest, or `points`), scaled from its units.

export const METRES_PER_UNIT = { m: 1, cm: 0.01, mm: 0.001, ft: 0.3048, in: 0.0254 };

const isVec3 = (v) => Array.isArray(v) && v.length === 3 && v.every(Number.isFinite);
const scaled = (v, s) => v.map((x) => x * s);
const plus = (a, b) => a.map((x, k) => x + b[k]);

function gridPoints(grid) {
    const points = [];
    for (let iv = 0; iv < grid.nv; ++iv) {
        for (let iu = 0; iu < grid.nu; ++iu) {
            const a = (iu + 0.5) / grid.nu;
            const b = (iv + 0.5) / grid.nv;
            points.push(plus(plus(grid.origin, scaled(grid.u, a)), scaled(grid.v, b)));
        }
    }
    return points;
}

const validGrid = (g) =>
    g &&
    isVec3(g.origin) &&
    isVec3(g.u) &&
    isVec3(g.v) &&
    Number.isInteger(g.nu) &&
    Number.isInteger(g.nv) &&
    g.nu > 0 &&
    g.nv > 0;

/// One cell's sides (u/nu, v/nv), for drawing a grid point as a tile.
const cellOf = (g, s) => ({ u: scaled(g.u, s / g.nu), v: scaled(g.v, s / g.nv) });

/// [{name, points: [[x,y,z] m], normal, cell: {u, v} | null}] in the order of result.sensors;
/// a set whose points are known neither way has no points (its numbers still go in the table).
export function sensorLayouts(result, scene) {
    const sets = Array.isArray(result?.sensors) ? result.sensors : [];
    const sceneSets = Array.isArray(scene?.sensors) ? scene.sensors : [];
    const scale = METRES_PER_UNIT[scene?.units ?? "m"] ?? 1;
    return sets.map((set, i) => {
        const fromScene = sceneSets.find((s) => s?.name === set.name) ?? sceneSets[i] ?? {};
        const normal = isVec3(set.normal)
            ? set.normal
            : isVec3(fromScene.normal)
              ? fromScene.normal
              : [0, 0, 1];
        const layout = { name: set.name, points: [], normal, cell: null };
        if (validGrid(set.grid) && Array.isArray(set.grid.points)) {
            layout.points = set.grid.points.filter(isVec3);
            layout.cell = cellOf(set.grid, 1);
        } else if (Array.isArray(set.points)) {
            layout.points = set.points.filter(isVec3);
        } else if (validGrid(fromScene.grid)) {
            layout.points = gridPoints(fromScene.grid).map((p) => scaled(p, scale));
            layout.cell = cellOf(fromScene.grid, scale);
        } else if (Array.isArray(fromScene.points)) {
            layout.points = fromScene.points.filter(isVec3).map((p) => scaled(p, scale));
        }
        return layout;
    });
}
