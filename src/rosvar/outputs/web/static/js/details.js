// The details of what is selected in the graph: one element (its attributes, presence,
// condition, file:line and, for one of several variants, what tells it from its twins), or
// a box of the overview (what it holds, with a button to open it), or a node's params (a
// page at a time). Closing the panel unselects the element: it opens again on the next
// click on the graph, not on the next step.

import { clashName, linkRows } from "./graph.js";
import { shortPath, entryFile } from "./names.js";

const SHOWN_APART = new Set(["id", "kind", "name", "presence", "condition", "filename", "line", "col",
                             "nodes", "names", "groups", "group", "groupName", "variant"]);
const PAGE = 50; // params listed at a time
const EDGES = new Set(["publishers", "subscribers", "servers", "clients"]);

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

function button(text, onClick, className = "") {
  const node = document.createElement("button");
  node.type = "button";
  node.textContent = text;
  node.className = className;
  node.addEventListener("click", onClick);
  return node;
}

function presenceBadge(presence) {
  const node = document.createElement("span");
  node.className = `presence ${presence}`;
  node.textContent = presence;
  return node;
}

export class DetailsPanel {
  // actions: {open(unitId), close(groupKey), unselect()} act on the graph.
  constructor(panel, body, closer, actions) {
    this.panel = panel;
    this.body = body;
    this.actions = actions;
    this.shown = null; // the unit id shown
    this.limit = PAGE;
    closer.addEventListener("click", () => { this.hide(); actions.unselect(); });
  }

  hide() {
    this.panel.hidden = true;
    this.shown = null;
  }

  // element: a graph unit's description (with its kind, unitId); state: for names and conflicts.
  show(element, state) {
    if (!element) { this.hide(); return; }
    if (element.unitId !== this.shown) this.limit = PAGE;
    this.shown = element.unitId;
    this.panel.hidden = false;
    const title = document.createElement("h2");
    const table = document.createElement("table");
    const extra = [];
    if (element.kind === "group") {
      title.textContent = element.name;
      table.append(row("holds", `${element.total.toLocaleString("en")} nodes (${element.present.toLocaleString("en")} present) from ${element.files.toLocaleString("en")} launch file${element.files === 1 ? "" : "s"}`));
      extra.push(button("Open this group", () => this.actions.open(element.unitId), "primary"));
    } else if (element.kind === "variants") {
      title.textContent = `${element.total} variants of ${element.name}`;
      table.append(row("present", `${element.present} of ${element.total}`));
      table.append(row("they differ in", element.differ.join(", ") || "their conditions"));
      extra.push(button("Show each variant", () => this.actions.open(element.unitId), "primary"));
    } else if (element.kind === "more") {
      title.textContent = `${element.hidden} more in ${element.name}`;
      extra.push(button("Show more", () => this.actions.open(element.unitId), "primary"));
    } else if (element.kind === "link") { // topics, services and actions between two closed boxes
      title.textContent = `${element.from} → ${element.to}`;
      for (const [count, names] of linkRows(element)) table.append(row(count, names));
    } else if (element.kind === "params") {
      title.textContent = `${element.params.length.toLocaleString("en")} params of ${element.name}`;
      this.paramRows(table, element.params);
      if (element.params.length > this.limit) {
        extra.push(button(`Show ${Math.min(PAGE, element.params.length - this.limit)} more`, () => {
          this.limit += PAGE;
          this.show(element, state);
        }));
      }
    } else {
      title.textContent = `${element.kind} ${element.name}`;
      this.elementRows(table, element, state);
      if (element.group) extra.push(button(`Close ${element.groupName}`, () => this.actions.close(element.group)));
    }
    const actions = document.createElement("div");
    actions.className = "actions";
    actions.append(...extra);
    this.body.replaceChildren(title, table, actions);
  }

  paramRows(table, params) {
    for (const param of params.slice(0, this.limit)) {
      const value = document.createElement("span");
      value.append(presenceBadge(param.presence), ` ${cell(param.value, "value")}`);
      value.title = `${param.filename}:${param.line}${param.condition ? ` — when ${param.condition}` : ""}`;
      table.append(row(param.name, value));
    }
  }

  elementRows(table, element, state) {
    table.append(row("presence", presenceBadge(element.presence)));
    table.append(row("condition", element.condition ?? (element.presence === "present" ? "always (decided)" : "—")));
    if (element.filename) table.append(row("declared at", `${element.filename}:${element.line}`));
    const entry = entryFile(element.id);
    if (entry) table.append(row("launched by", shortPath(entry)));
    if (element.variant) {
      const { at, of, differ } = element.variant;
      table.append(row("variant", `${at} of ${of}; they differ in ${differ.join(", ") || "their conditions"}`));
    }
    // a topic's, service's or action's nodes come with their names
    const names = new Map((element.nodes ?? []).map((id, at) => [id, element.names?.[at]]));
    if (element.nodes) {
      table.append(row("nodes", [...new Set(element.nodes.map((id) => names.get(id) ?? id))].join(", ") || "—"));
    }
    for (const [key, value] of Object.entries(element)) {
      if (SHOWN_APART.has(key) || key === "unitId") continue;
      // a name's publishers, subscribers, servers or clients: nodes, each when it uses it
      const edges = EDGES.has(key) && Array.isArray(value);
      table.append(row(key, edges ? value.map((edge) => `${names.get(edge.node) ?? edge.node}`
        + (edge.condition ? ` (when ${edge.condition})` : "")).join(", ") || "—"
        : key === "types" && Array.isArray(value) ? value.join(", ") || "—" : cell(value, key)));
    }
    const name = clashName(element.kind, element.name);
    const clashes = state.conflicts.filter((conflict) => conflict.names.includes(name));
    for (const conflict of clashes) {
      table.append(row(`⚠ ${conflict.status} conflict`,
        `${conflict.files.map(shortPath).join(" and ")}${conflict.condition ? ` when ${conflict.condition}` : ""}`));
    }
  }
}
