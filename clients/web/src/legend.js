// The colour legend beside the view: a vertical bar of the scale in use, with its unit and ticks.
import { falseColour, formatValue, grey, srgbEncode, ticks } from "./colour_scale.js";

const TITLES = { luminance: "Luminance (cd/m²)", illuminance: "Illuminance (lux)" };

export class Legend {
    constructor(element) {
        this.element = element;
        this.title = element.querySelector(".legend-title");
        this.bar = element.querySelector("canvas");
        this.labels = element.querySelector(".legend-ticks");
    }

    /// `spec`: {kind: "luminance" | "illuminance", top} from RoomView.legend().
    show({ kind, top }) {
        this.element.dataset.kind = kind;
        this.title.textContent = TITLES[kind];
        const colour = kind === "illuminance" ? falseColour : grey;
        const context = this.bar.getContext("2d");
        const { width, height } = this.bar;
        for (let y = 0; y < height; ++y) {
            const rgb = colour(1 - y / (height - 1)).map((c) => Math.round(255 * srgbEncode(c)));
            context.fillStyle = `rgb(${rgb.join(",")})`;
            context.fillRect(0, y, width, 1);
        }
        this.labels.replaceChildren(
            ...ticks(top, 4)
                .reverse()
                .map((value) =>
                    Object.assign(document.createElement("span"), {
                        textContent: formatValue(value),
                    }),
                ),
        );
    }
}
