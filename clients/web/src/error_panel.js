// Errors shown where they are: each problem's JSON pointer and message, and the lines of the
// submitted scene at that pointer, highlighted (the service's `invalid_scene` problems, or a
// file the viewer could not read for a `*_file` reference).
import { excerpt, layoutJson } from "./json_layout.js";

export class ErrorPanel {
    constructor(element) {
        this.element = element;
    }

    clear() {
        this.element.replaceChildren();
        this.element.hidden = true;
    }

    /// `error`: {message, code?, problems: [{pointer, message}]}; `scene`: what was sent, or null.
    show(error, scene) {
        const layout = scene ? layoutJson(scene) : null;
        const problems = error.problems?.length
            ? error.problems
            : [{ pointer: "", message: error.message }];
        const heading = Object.assign(document.createElement("h3"), {
            textContent: error.code ? `Refused (${error.code})` : "Refused",
        });
        this.element.replaceChildren(heading, ...problems.map((p) => problemView(p, layout)));
        this.element.hidden = false;
        this.element.querySelector(".at-pointer")?.scrollIntoView({ block: "nearest" });
    }
}

function problemView(problem, layout) {
    const item = document.createElement("div");
    item.className = "problem";
    item.dataset.pointer = problem.pointer;
    const title = document.createElement("p");
    title.append(
        Object.assign(document.createElement("code"), {
            className: "pointer",
            textContent: problem.pointer || "/",
        }),
        " ",
        Object.assign(document.createElement("span"), {
            className: "message",
            textContent: problem.message,
        }),
    );
    item.append(title);
    if (layout) {
        const at = excerpt(layout, problem.pointer);
        const pre = document.createElement("pre");
        pre.className = "excerpt";
        for (let i = at.from; i <= at.to; ++i) {
            const line = document.createElement("span");
            line.textContent = `${layout.lines[i]}\n`;
            if (i >= at.first && i <= at.last)
                line.className = at.exact ? "at-pointer" : "at-pointer missing";
            pre.append(line);
        }
        item.append(pre);
    }
    return item;
}
