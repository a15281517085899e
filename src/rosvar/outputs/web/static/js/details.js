// The details of one graph element: its attributes, presence, condition and file:line.

import { clashName } from "./graph.js";

const SHOWN_APART = new Set(["id", "kind", "name", "presence", "condition", "filename", "line", "col", "nodes"]);

// A node's remaps and env settings whose own condition is still open.
function undetermined(settings) {
  const arrow = { remap: "→", env: "=" };
  return settings.map(({ kind, pair, condition }) =>
    `${kind} ${pair[0]} ${arrow[kind]} ${pair[1]} when ${condition}`).join("; ");
}

function cell(value, key) {
  if (value === null || value === undefined) return "—";
  if (key === "undetermined") return undetermined(value);
  if (typeof value === "object") return JSON.stringify(value);
  return String(value);
}

function row(label, content) {
  const tr = document.createElement("tr");
  const th = document.createElement("th");
  th.textContent = label;
  const td = document.createElement("td");
  td.append(content);
  tr.append(th, td);
  return tr;
}

export class DetailsPanel {
  constructor(panel, body, closer) {
    this.panel = panel;
    this.body = body;
    closer.addEventListener("click", () => this.show(null));
  }

  // element: a graph element's JSON plus its kind; state: for topics' node names and conflicts.
  show(element, state) {
    this.panel.hidden = !element || element.kind === "namespace";
    if (this.panel.hidden) return;
    const title = document.createElement("h2");
    title.textContent = `${element.kind} ${element.name}`;
    const table = document.createElement("table");
    const presence = document.createElement("span");
    presence.className = `presence ${element.presence}`;
    presence.textContent = element.presence;
    table.append(row("presence", presence));
    table.append(row("condition", element.condition ?? (element.presence === "present" ? "always (decided)" : "—")));
    if (element.filename) table.append(row("declared at", `${element.filename}:${element.line}`));
    if (element.nodes) {
      const names = new Map(state.graph.nodes.map((node) => [node.id, node.name]));
      table.append(row("nodes", element.nodes.map((id) => names.get(id) ?? id).join(", ") || "—"));
    }
    for (const [key, value] of Object.entries(element)) {
      if (!SHOWN_APART.has(key)) table.append(row(key, cell(value, key)));
    }
    const name = clashName(element.kind, element.name);
    const clashes = state.conflicts.filter((conflict) => conflict.names.includes(name));
    for (const conflict of clashes) {
      table.append(row(`⚠ ${conflict.status} conflict`,
        `${conflict.files.join(" and ")}${conflict.condition ? ` when ${conflict.condition}` : ""}`));
    }
    this.body.replaceChildren(title, table);
  }
}
