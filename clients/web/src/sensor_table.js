// The work-plane table: each sensor set's mean illuminance Ē, E_min, E_max and uniformity
// U₀ = E_min / Ē (EN 12464-1), as the result gives them.
import { formatValue } from "./colour_scale.js";

const cell = (tag, text, className) =>
    Object.assign(document.createElement(tag), { textContent: text, className: className ?? "" });

export function renderSensorTable(table, result) {
    const body = table.querySelector("tbody");
    const sets = Array.isArray(result?.sensors) ? result.sensors : [];
    body.replaceChildren(
        ...sets.map((set) => {
            const row = document.createElement("tr");
            row.dataset.sensor = set.name;
            const u0 = set.u0 ?? set.uniformity;
            row.append(
                cell("th", set.name),
                cell("td", String(set.illuminance?.length ?? 0), "num"),
                cell("td", formatValue(set.average), "num average"),
                cell("td", formatValue(set.min), "num min"),
                cell("td", formatValue(set.max), "num max"),
                cell("td", Number.isFinite(u0) ? u0.toFixed(2) : "–", "num u0"),
            );
            return row;
        }),
    );
    table.hidden = sets.length === 0;
}
