// The service's jobs, newest first: name (when this browser submitted it), status and time;
// a click opens one.

export function renderJobs(list, jobs, { currentId, names, open }) {
    list.replaceChildren(
        ...jobs.map((job) => {
            const item = document.createElement("li");
            const button = document.createElement("button");
            button.type = "button";
            button.dataset.job = job.id;
            button.dataset.status = job.status;
            if (job.id === currentId) button.classList.add("current");
            const created = job.created ? new Date(job.created).toLocaleTimeString() : "";
            button.append(
                Object.assign(document.createElement("span"), {
                    className: "job-name",
                    textContent: names[job.id] ?? job.id.slice(0, 8),
                }),
                Object.assign(document.createElement("span"), {
                    className: `badge ${job.status}`,
                    textContent: job.status,
                }),
                Object.assign(document.createElement("span"), {
                    className: "job-time",
                    textContent: created,
                }),
            );
            button.addEventListener("click", () => open(job.id));
            item.append(button);
            return item;
        }),
    );
}
