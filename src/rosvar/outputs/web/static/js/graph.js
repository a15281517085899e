// The computation graph: ROS nodes (and test nodes), the topics, services and actions they
// are wired to and (on request) params, drawn with Cytoscape.js.
//
// A large workspace has thousands of graph entries (Husky: 985 nodes, 7,500 params), far more
// than a readable drawing holds, so the view aggregates: entries are grouped (by package then
// launch file, by launch file, or by namespace), every group is drawn as one box with its
// counts until it is expanded, entries of one name within a group (variants) fold into one
// box, an expanded group shows a page of its members at a time, and params are never drawn
// one by one (a node's params are one tag, listed in the details). Groups holding elements of
// the selected launch files open by themselves: those come first. The state carries the
// groups' summaries only (the server groups, docs/web.md "Overview mode"): the members of
// the groups drawn open, and the topics, services and actions, are fetched for each state.
// A state with more of these than LINKED_ABOVE (Husky with its dependencies as features:
// thousands) would fetch megabytes of them per step to draw each one: then only those of the
// groups drawn open are fetched, and two closed boxes are joined by one edge per direction
// from the links between the boxes drawn (how many names, of which kinds; /api/links).
//
// Graph ids are stable across steps. When the drawn units appear or go the layout runs again
// and every unit moves to its new place in an animation (new units grow from the box they
// came out of); otherwise a step only restyles the units (present/undetermined, conflicts).

import { baseName, entryFile, shortPath } from "./names.js";

cytoscape.use(cytoscapeDagre);

const LAYERED = { name: "dagre", rankDir: "LR", nodeSep: 14, rankSep: 110, animate: false, fit: false,
                  nodeDimensionsIncludeLabels: true };
const CELL = { width: 250, height: 80 }; // a grid cell: a unit and its two-line label
const PAGE = 24; // members of an expanded group drawn at a time
const ANIMATION_MS = 350;
const ZOOM = { legible: 0.6, max: 1.6 }; // grids are as wide as the view at a legible zoom; a fit zooms in up to max
const PADDING = 30;
const QUIET_LINKS_ABOVE = 20; // more links drawn than this: labels only on a selected or hovered box's links
const LINKED_ABOVE = 100; // topics, services and actions drawn one by one at most, else links (Husky has 132)

const STYLE = [
  { selector: "node", style: {
    label: "data(label)", "font-size": 12, "text-valign": "bottom", "text-margin-y": 3,
    "min-zoomed-font-size": 6, "text-wrap": "wrap", "text-max-width": CELL.width - 16,
    "text-background-color": "#fff", "text-background-opacity": 0.8, "text-background-padding": 1,
    "border-width": 1.5, "border-color": "#333",
  } },
  { selector: 'node[kind = "node"]', style: { shape: "ellipse", "background-color": "#fff", width: 26, height: 26 } },
  { selector: 'node[kind = "test"]', style: { shape: "ellipse", "background-color": "#fff", "border-style": "double", "border-width": 4, width: 26, height: 26 } },
  { selector: 'node[kind = "topic"]', style: { shape: "round-rectangle", "background-color": "#8ecae6", width: 24, height: 14 } },
  { selector: 'node[kind = "service"]', style: { shape: "diamond", "background-color": "#b5e48c", width: 22, height: 22 } },
  { selector: 'node[kind = "action"]', style: { shape: "hexagon", "background-color": "#cdb4db", width: 26, height: 18 } },
  { selector: 'edge[kind = "service"], edge[kind = "action"]', style: { "target-arrow-shape": "triangle", "target-arrow-color": "#9aa3b5", "arrow-scale": 0.8 } },
  { selector: 'node[kind = "params"]', style: { shape: "tag", "background-color": "#ffd166", width: 22, height: 14, "font-size": 11 } },
  // boxes carry their label inside, sized to it
  { selector: 'node[kind = "group"], node[kind = "variants"], node[kind = "more"]', style: {
    shape: "round-rectangle", width: "data(width)", height: 40, "text-valign": "center",
    "text-margin-y": 0, "text-background-opacity": 0, "line-height": 1.3,
  } },
  { selector: 'node[kind = "group"]', style: { "background-color": "#e8edf7", "border-color": "#6b7ba3", "font-weight": "bold" } },
  { selector: 'node[kind = "variants"]', style: { "background-color": "#fff", "border-width": 4, "border-style": "double" } },
  { selector: 'node[kind = "more"]', style: { "background-color": "#f6f7f9", "border-style": "dotted", height: 26 } },
  { selector: "edge", style: { width: 1.2, "line-color": "#9aa3b5", "curve-style": "bezier" } },
  { selector: 'edge[kind = "params"]', style: { "line-color": "#e0b54a", "line-style": "dotted" } },
  { selector: 'edge[kind = "link"]', style: {
    width: "data(width)", "line-color": "#7d8aa8", "target-arrow-shape": "triangle", "target-arrow-color": "#7d8aa8",
    label: "data(label)", "font-size": 10, color: "#4a5570", "text-background-color": "#fff",
    "text-background-opacity": 0.8, "text-background-padding": 1,
  } },
  // crowded links keep their labels for the box under the pointer or selected (and the link itself)
  { selector: 'edge[kind = "link"].quiet', style: { "text-opacity": 0, "text-background-opacity": 0 } },
  { selector: 'edge[kind = "link"].quiet.near, edge[kind = "link"].quiet.pointed, edge[kind = "link"].quiet:selected',
    style: { "text-opacity": 1, "text-background-opacity": 0.8, "z-index": 10 } },
  { selector: ".undetermined", style: { "border-style": "dashed", "line-style": "dashed", "background-opacity": 0.7 } },
  { selector: "node.on-event", style: { "border-style": "double", "border-width": 4, "border-color": "#7b4fc9" } },
  { selector: "node.conflict", style: { "border-color": "#b42318", "border-width": 4, color: "#b42318" } },
  { selector: "node.match", style: { "border-color": "#2f6fdb", "border-width": 4 } },
  { selector: "node.queried", style: { "border-color": "#d7191c", "border-width": 5, color: "#d7191c", "font-weight": "bold" } },
  { selector: ":selected", style: { "overlay-color": "#2f6fdb", "overlay-opacity": 0.18, "overlay-padding": 5 } },
  { selector: ".faded", style: { opacity: 0.15 } },
  { selector: ".hidden", style: { display: "none" } },
];

const PREFIX = { node: "n:", test: "n:", topic: "t:", service: "s:", action: "a:", params: "p:", group: "g:", variants: "v:", more: "m:", link: "l:" };

// The kinds of names nodes are wired to, their lists in the graph, and the sides of their
// edges (the list feeding the name, the list using it).
const CHANNELS = [["topic", "topics"], ["service", "services"], ["action", "actions"]];
const SIDES = { topic: ["publishers", "subscribers"], service: ["servers", "clients"], action: ["servers", "clients"] };

// Every "kind name" (e.g. "node /controller") that takes part in a conflict of the state.
function conflictNames(conflicts) {
  const names = new Set();
  for (const conflict of conflicts) for (const name of conflict.names) names.add(name);
  return names;
}

// How a conflict names an element: its kind ("test" nodes clash as nodes) and ROS name.
export function clashName(kind, name) {
  return `${kind === "test" ? "node" : kind} ${name}`;
}

// A label line no longer than a box holds: long paths keep their end.
function fitted(text, room = 28) {
  return text.length > room ? `…${text.slice(text.length - room + 1)}` : text;
}

function plural(count, word) {
  return `${count.toLocaleString("en")} ${word}${count === 1 ? "" : "s"}`;
}

// A box as wide as its longest line (12px text), no wider than a grid cell.
function widthFor(label) {
  const longest = Math.max(...String(label).split("\n").map((line) => line.length));
  return Math.min(CELL.width - 16, 20 + 8 * longest);
}

// The fields on which variants of one name differ, for telling them apart.
const SAME_FOR_VARIANTS = new Set(["id", "presence", "condition", "col", "kind"]);

function differences(variants) {
  const keys = new Set(variants.flatMap((v) => Object.keys(v)));
  const differ = [];
  for (const key of keys) {
    if (SAME_FOR_VARIANTS.has(key)) continue;
    const seen = new Set(variants.map((v) => JSON.stringify(v[key] ?? null)));
    if (seen.size > 1) differ.push(key);
  }
  if (new Set(variants.map((v) => entryFile(v.id))).size > 1) differ.unshift("launched by");
  if (new Set(variants.map((v) => v.condition)).size > 1) differ.push("condition");
  return differ;
}

function flat(value) {
  return (typeof value === "string" ? value : JSON.stringify(value ?? null)).replace(/\s+/g, " ");
}

// Where the values of a field start to differ among variants (their common prefix's length).
function divergence(variants, key) {
  const texts = variants.map((v) => flat(v[key]));
  let at = 0;
  while (at < texts[0].length && texts.every((t) => t[at] === texts[0][at])) at += 1;
  return at;
}

// One line telling a variant from its twins: the first field that differs, from where it
// differs.
function variantHint(variant, differ, variants) {
  const key = differ[0];
  if (key === undefined) return "";
  if (key === "launched by") return `by ${shortPath(entryFile(variant.id))}`;
  if (key === "filename" || key === "line") return `@${baseName(variant.filename)}:${variant.line}`;
  const text = flat(variant[key]);
  const from = Math.max(0, divergence(variants, key) - 6);
  const shown = text.slice(from, from + 34);
  return `${key}: ${from ? "…" : ""}${shown}${from + 34 < text.length ? "…" : ""}`;
}

// What a link edge stands for: per kind (topics first), how many names and how many of them
// are present.
export function linkRows(link) {
  return CHANNELS.filter(([, list]) => list in link.counts).map(([kind, list]) => {
    const [present, possible] = link.counts[list];
    return [plural(possible, kind), `${present.toLocaleString("en")} present`];
  });
}

// A link edge's tooltip.
function linkText(link) {
  return [`${link.from} → ${link.to}`, ...linkRows(link).map(([count, present]) => `${count} (${present})`)].join("\n");
}

// A group of the overview, from its summary (the server's, docs/web.md "Overview mode"):
// its subgroups that hold nodes, those that hold only params (never drawn: their params go
// with it), and the members fetched for it when it is drawn open.
class Group {
  constructor(key, label, parent, summary) {
    this.key = key;
    this.label = label;
    this.parent = parent;
    this.summary = summary;
    this.children = new Map(); // key → subgroup holding nodes
    this.bare = []; // subgroups holding params only
    this.members = []; // [kind, entry] of its own nodes, as fetched
    this.params = []; // its own params and its bare subgroups', as fetched
  }

  count(kind, at = 1) {
    if (this.summary) return this.summary[kind][at];
    return [...this.children.values(), ...this.bare].reduce((sum, c) => sum + c.count(kind, at), 0);
  }

  // Entries of a kind that are its own, not in a subgroup.
  own(kind) {
    const inside = [...this.children.values(), ...this.bare].reduce((sum, c) => sum + c.count(kind), 0);
    return this.count(kind) - inside;
  }

  // Its own names and its subgroups', for the search.
  names() {
    return [...(this.summary?.names ?? []), ...[...this.children.values()].flatMap((c) => c.names())];
  }
}

// The groups of a state's summaries (parents come first), under a root.
function groupTree(summaries) {
  const root = new Group("", "", null, null);
  const groups = new Map([["", root]]);
  for (const summary of summaries) {
    const parent = groups.get(summary.parent);
    const group = new Group(summary.id, summary.label, parent, summary);
    groups.set(summary.id, group);
    if (summary.nodes[1] > 0) parent.children.set(summary.id, group);
    else parent.bare.push(group);
  }
  return root;
}

export class GraphView {
  // members(group, kind, page) fetches a page of a group's members (the API's /api/group),
  // links(groups) the links between groups (/api/links).
  // onSelect(element | null, byUser) is called with the selected unit's description
  // whenever the selection (byUser: true) or the selected unit's data (false) changes.
  // onDrawn() is called after every redraw.
  constructor(container, members, links, onSelect, onDrawn = () => {}) {
    this.container = container;
    this.cy = cytoscape({ container, style: STYLE, minZoom: 0.05, maxZoom: 4, boxSelectionEnabled: false });
    this.options = { params: false };
    this.expanded = new Set(); // group keys the user opened
    this.collapsed = new Set(); // group keys the user closed (even if they would open themselves)
    this.pages = new Map(); // group key → members shown
    this.focused = null; // unit id whose neighbourhood alone is shown
    this.needle = "";
    this.marked = new Map(); // who marks (a query, a finding) → [graph entry id, its group key]
    this.state = null;
    this.members = members;
    this.links = links;
    this.linking = []; // the links between the closed boxes drawn, as fetched
    this.fetched = new Map(); // "group kind page" → the answer's promise, for the state drawn
    this.channels = { topic: [], service: [], action: [] }; // every one, as fetched
    this.units = new Map(); // unit id → {names: lowercased member names} for the search
    this.unitOf = new Map(); // graph entry id → the unit that draws it
    this.boxOf = () => undefined; // group key → the unit that draws its members unfetched
    this.onSelect = onSelect;
    this.onDrawn = onDrawn;
    this.queue = Promise.resolve();
    this.pending = 0; // draws asked for and not done
    this.layoutRuns = 0;
    this.layoutsDone = 0;
    this.container.dataset.layout = "done";
    this.moved = false; // the user panned or zoomed since the view was last fitted to everything
    this.settle = null; // what ends the running layout once the view is where it goes
    this.cy.on("dragpan scrollzoom pinchzoom", () => { this.moved = true; });
    this.refit = false; // the canvas changed size while a layout ran: fit when it ends
    this.size = null; // the canvas's size as last reported
    new ResizeObserver((entries) => this.resized(entries[entries.length - 1].contentRect)).observe(container);
    this.cy.on("select unselect", () => { this.markNear(); this.onSelect(this.selectedElement(), true); });
    this.cy.on("mouseover", "node", (event) => event.target.connectedEdges('[kind = "link"]').addClass("pointed"));
    this.cy.on("mouseout", "node", (event) => event.target.connectedEdges('[kind = "link"]').removeClass("pointed"));
    this.cy.on("dbltap", "node", (event) => this.open(event.target.id()));
    this.cy.on("mouseover", 'edge[kind = "link"]', (event) => { this.container.title = linkText(event.target.data("element")); });
    this.cy.on("mouseout", 'edge[kind = "link"]', () => { this.container.title = ""; });
  }

  // The links of the selected boxes are "near": they show their labels among quiet ones.
  markNear() {
    this.cy.edges(".near").removeClass("near");
    this.cy.nodes(":selected").connectedEdges('[kind = "link"]').addClass("near");
  }

  selectedElement() {
    const selected = this.cy.$(":selected");
    if (selected.empty() || !selected[0].data("element")) return null;
    return { ...selected[0].data("element"), unitId: selected[0].id() };
  }

  // A new state: its groups drawn, the members of the open ones fetched again.
  update(state) {
    if (this.state && state.grouping !== this.state.grouping) {
      this.expanded.clear(); // other groups: back to the overview
      this.collapsed.clear();
      this.pages.clear();
      this.focused = null;
    }
    if (state.version !== this.state?.version) this.fetched.clear();
    this.state = state;
    return this.redraw();
  }

  setOption(name, value) {
    this.options[name] = value;
    return this.redraw();
  }

  // Opens a group or a variants box (or shows more of a group), by unit id.
  open(unitId) {
    const element = this.cy.getElementById(unitId).data("element");
    if (!element) return this.queue;
    if (element.kind === "more") this.pages.set(element.group, (this.pages.get(element.group) ?? PAGE) + PAGE);
    else if (element.kind === "group" || element.kind === "variants") {
      this.collapsed.delete(element.key);
      this.expanded.add(element.key);
      this.origin = this.cy.getElementById(unitId).position();
    } else return this.queue;
    this.cy.$(":selected").unselect();
    return this.redraw();
  }

  // Closes the group a unit is drawn in (it is drawn as one box again).
  close(groupKey) {
    this.expanded.delete(groupKey);
    for (const key of [...this.expanded]) if (key.startsWith(`${groupKey}\u0001`)) this.expanded.delete(key);
    this.collapsed.add(groupKey);
    return this.redraw();
  }

  // Back to the overview: every group closed but those of the selected files.
  overview() {
    this.expanded.clear();
    this.collapsed.clear();
    this.pages.clear();
    this.focused = null;
    return this.redraw();
  }

  // Draws the state again once the members it needs are fetched; draws run one after another.
  // (#graph[data-layout] is "running" until the last is drawn and laid out).
  redraw() {
    this.container.dataset.layout = "running";
    this.pending += 1;
    this.queue = this.queue.catch(() => {}).then(() => this.draw()).finally(() => {
      this.pending -= 1;
      if (!this.pending && this.layoutsDone === this.layoutRuns) this.container.dataset.layout = "done";
    });
    return this.queue;
  }

  async draw() {
    if (!this.state) return;
    const root = groupTree(this.state.graph.groups);
    await this.fetch(root);
    this.render(root);
  }

  // -- members --------------------------------------------------------------------------------
  // Whether a group is drawn opened: the user said so, or it holds nodes of selected files.
  isOpen(group) {
    if (this.expanded.has(group.key)) return true;
    if (this.collapsed.has(group.key)) return false;
    return group.summary.selected > 0;
  }

  // A group with one subgroup and nothing else opens with it: no click for nothing.
  opensWith(group) {
    return group.children.size === 1 && group.own("nodes") === 0;
  }

  // The groups drawn open, outermost first.
  opened(root) {
    const found = [];
    const walk = (group) => {
      for (const child of group.children.values()) {
        if (this.opensWith(child) || this.isOpen(child)) { found.push(child); walk(child); }
      }
    };
    walk(root);
    return found;
  }

  // A page of a group's members in the state drawn, fetched once.
  page(group, kind, page) {
    const key = `${group} ${kind} ${page}`;
    if (!this.fetched.has(key)) {
      const answer = this.members(group, kind, page);
      answer.catch(() => this.fetched.delete(key));
      this.fetched.set(key, answer);
    }
    return this.fetched.get(key);
  }

  // The members of a group's first `most` pages (every page by default).
  async pagesOf(group, kind, most = Infinity) {
    const first = await this.page(group, kind, 0);
    const rest = [];
    for (let page = 1; page < Math.min(first.pages, most); page += 1) rest.push(this.page(group, kind, page));
    return [first, ...await Promise.all(rest)].flatMap((answer) => answer.members);
  }

  // Whether the state has too many topics, services and actions to draw them all: then closed
  // boxes are joined by the state's links.
  linked() {
    return Object.values(this.state?.channels ?? {}).reduce((sum, count) => sum + count, 0) > LINKED_ABOVE;
  }

  // The groups whose topics, services and actions are fetched: the root's (all of them), or
  // when linked, those of the open groups drawing nodes one by one (not under another such:
  // a group's are those of the nodes under it at any level).
  wired(root) {
    if (!this.linked()) return [root];
    const found = [];
    for (const group of this.opened(root)) {
      if (group.own("nodes") > 0 && !found.some((outer) => group.key.startsWith(`${outer.key}\u0001`))) found.push(group);
    }
    return found;
  }

  // The groups drawn as closed boxes, as emit() in plan() draws them.
  closed(root) {
    const found = [];
    const walk = (group) => {
      for (const child of group.children.values()) {
        if (this.opensWith(child) || this.isOpen(child)) walk(child);
        else found.push(child.key);
      }
    };
    walk(root);
    return found;
  }

  // The links between the closed boxes in the state drawn, fetched once per set of boxes.
  linksOf(keys) {
    const key = `links ${keys.join("\u0003")}`;
    if (!this.fetched.has(key)) {
      const answer = this.links(keys);
      answer.catch(() => this.fetched.delete(key));
      this.fetched.set(key, answer);
    }
    return this.fetched.get(key);
  }

  // Fetches what the drawing needs: the nodes (and params) of the open groups, the topics,
  // services and actions of wired(root), and when linked the links between the closed boxes.
  async fetch(root) {
    const jobs = [];
    this.linking = [];
    if (this.linked()) {
      const boxes = this.closed(root);
      if (boxes.length > 1) jobs.push(this.linksOf(boxes).then((answer) => { this.linking = answer.links; }));
    }
    // a group's own params and those of its subgroups holding no node
    const params = (into, group = into) => {
      if (group.own("params") > 0) jobs.push(this.pagesOf(group.key, "params").then((found) => into.params.push(...found)));
      for (const bare of group.bare) params(into, bare);
    };
    for (const group of this.opened(root)) {
      if (group.own("nodes") > 0) {
        const pages = Math.ceil((this.pages.get(group.key) ?? PAGE) / PAGE);
        jobs.push(this.pagesOf(group.key, "nodes", pages).then((found) => {
          group.members = found.map((entry) => [entry.kind, entry]);
        }));
      }
      if (this.options.params) params(group);
    }
    if (this.options.params) params(root);
    const wired = this.wired(root);
    for (const [kind, list] of CHANNELS) {
      this.channels[kind] = [];
      const from = wired.filter((group) => group.count(list) > 0);
      if (!from.length) continue;
      jobs.push(Promise.all(from.map((group) => this.pagesOf(group.key, list))).then((found) => {
        const byId = new Map(found.flat().map((named) => [named.id, named])); // once, if under two
        this.channels[kind] = [...byId.values()];
      }));
    }
    await Promise.all(jobs);
  }

  // -- units ----------------------------------------------------------------------------------
  plan(state, root) {
    const clashing = conflictNames(state.conflicts);
    const wanted = [];
    const unitOf = new Map();
    const searchNames = new Map();
    const drawnNodes = new Map(); // ROS node name → unit ids of nodes drawn one by one

    const presenceClass = (present, total) => (present === total ? "present" : "undetermined");
    const addGroupUnit = (group) => {
      const id = PREFIX.group + group.key;
      const total = group.count("nodes");
      const present = group.count("nodes", 0);
      const label = `${group.summary.conflict ? "⚠ " : ""}${fitted(group.label)}\n${plural(total, "node")}`;
      const element = { kind: "group", key: group.key, name: group.label, total, present, files: group.summary.files };
      wanted.push({ group: "nodes", classes: [presenceClass(present, total), group.summary.conflict ? "conflict" : ""].join(" "),
                    data: { id, kind: "group", label, width: widthFor(label), element, owner: group.key, params: group.count("params") } });
      searchNames.set(id, group.names().map((name) => String(name).toLowerCase()));
      return id;
    };
    const addNode = (kind, item, hint, group, variant = null) => {
      const id = PREFIX[kind] + item.id;
      const clash = clashing.has(clashName(kind, item.name));
      const label = `${clash ? "⚠ " : ""}${item.name}${hint ? `\n${hint}` : ""}`;
      const onEvent = String(item.trigger ?? "").startsWith("on_"); // an event handler starts it
      wanted.push({ group: "nodes", classes: [item.presence, clash ? "conflict" : "", onEvent ? "on-event" : ""].join(" "),
                    data: { id, kind, label, owner: item.id, element: { kind, ...item, group: group.key, groupName: group.label, variant } } });
      unitOf.set(item.id, id);
      searchNames.set(id, [String(item.name).toLowerCase()]);
      if (!drawnNodes.has(item.name)) drawnNodes.set(item.name, []);
      drawnNodes.get(item.name).push(id);
    };
    // the members of a group not drawn: `hidden` those fetched, `names` all their names
    const addMore = (group, count, hidden, names) => {
      const id = PREFIX.more + group.key;
      wanted.push({ group: "nodes", classes: "",
                    data: { id, kind: "more", label: `+${count} more`, width: widthFor(`+${count} more`),
                            element: { kind: "more", group: group.key, name: group.label, hidden: count } } });
      for (const [, item] of hidden) unitOf.set(item.id, id);
      searchNames.set(id, names.map((name) => String(name).toLowerCase()));
    };
    const emitMembers = (group) => {
      const byName = new Map();
      for (const [kind, item] of group.members) {
        if (!byName.has(item.name)) byName.set(item.name, []);
        byName.get(item.name).push([kind, item]);
      }
      const names = [...byName.keys()].sort();
      const limit = this.pages.get(group.key) ?? PAGE;
      const hidden = [];
      let shown = 0;
      for (const name of names) {
        const twins = byName.get(name);
        if (shown >= limit) { hidden.push(...twins); continue; }
        shown += 1;
        const key = `${group.key}\u0001=${name}`;
        if (twins.length === 1) { addNode(twins[0][0], twins[0][1], "", group); continue; }
        const items = twins.map(([, item]) => item);
        const differ = differences(items);
        if (this.expanded.has(key)) {
          const variants = { key, label: name };
          const page = this.pages.get(key) ?? PAGE;
          const seen = new Map(); // hint → times used: equal hints get a number
          twins.slice(0, page).forEach(([kind, item], index) => {
            let hint = variantHint(item, differ, items);
            if (seen.has(hint) || !hint) hint = `${hint} (${index + 1} of ${twins.length})`.trim();
            seen.set(hint, true);
            addNode(kind, item, hint, variants, { at: index + 1, of: twins.length, differ });
          });
          if (twins.length > page) addMore(variants, twins.length - page, twins.slice(page), [name]);
          continue;
        }
        const present = items.filter((item) => item.presence === "present").length;
        const conflict = items.some((item) => clashing.has(clashName("node", item.name)));
        const id = PREFIX.variants + key;
        const label = `${conflict ? "⚠ " : ""}${fitted(name)}\n${twins.length} variants`;
        wanted.push({ group: "nodes", classes: [presenceClass(present, twins.length), conflict ? "conflict" : ""].join(" "),
                      data: { id, kind: "variants", label, width: widthFor(label), owner: key,
                              element: { kind: "variants", key, name, total: twins.length, present, differ } } });
        for (const item of items) unitOf.set(item.id, id);
        searchNames.set(id, [String(name).toLowerCase()]);
      }
      const unfetched = group.own("nodes") - group.members.length;
      if (hidden.length || unfetched > 0) {
        const drawnNames = new Set(names.slice(0, limit));
        const rest = (group.summary?.names ?? []).filter((name) => !drawnNames.has(name));
        addMore(group, hidden.length + unfetched, hidden, rest);
      }
    };
    const opened = new Map(); // key → the groups drawn open
    const emit = (group) => {
      for (const child of [...group.children.values()].sort((a, b) => a.label.localeCompare(b.label))) {
        if (this.opensWith(child) || this.isOpen(child)) {
          opened.set(child.key, child);
          emit(child);
        }
        else addGroupUnit(child);
      }
      emitMembers(group);
    };
    emit(root);

    // the unit drawing the members of a group that are not fetched: its "+N more" box, or
    // the closed box it is in
    const drawn = new Map(wanted.map((item) => [item.data.id, item.data.element?.name]));
    const boxOf = (key) => {
      if (key === null || key === undefined) return undefined;
      if (drawn.has(PREFIX.more + key)) return PREFIX.more + key;
      for (let at = key; at; at = at.slice(0, at.lastIndexOf("\u0001"))) {
        if (drawn.has(PREFIX.group + at)) return PREFIX.group + at;
      }
      return undefined;
    };

    // topics, services and actions: one by one, wired to whatever unit draws each of their
    // nodes; an edge points the way data goes (publisher → topic → subscriber, client →
    // service → server)
    for (const [kind] of CHANNELS) {
      const [feeding, using] = SIDES[kind];
      for (const named of this.channels[kind]) {
        const id = PREFIX[kind] + named.id;
        wanted.push({ group: "nodes", classes: named.presence, data: { id, kind, label: named.name, owner: named.id, element: { kind, ...named } } });
        unitOf.set(named.id, id);
        searchNames.set(id, [String(named.name).toLowerCase()]);
        const drawer = (node, at) => unitOf.get(node) ?? boxOf(named.groups[at]);
        const where = new Map(named.nodes.map((node, at) => [node, drawer(node, at)]));
        // a unit whose nodes only use the name (by their interfaces) is at its far end
        const users = new Set((named[using] || []).map((edge) => where.get(edge.node)));
        const feeders = new Set((named[feeding] || []).map((edge) => where.get(edge.node)));
        for (const unit of new Set([...where.values()].filter(Boolean))) {
          const uses = users.has(unit) && !feeders.has(unit);
          // a topic flows to its users, a request from a client to the service's server
          const towardsUnit = kind === "topic" ? uses : !uses;
          const [source, target] = towardsUnit ? [id, unit] : [unit, id];
          wanted.push({ group: "edges", classes: named.presence === "undetermined" ? "undetermined" : "",
                        data: { id: `e:${named.id}:${unit}`, kind, owner: named.id, source, target } });
        }
      }
    }
    if (this.linked()) this.linkEdges(drawn, wanted);
    if (this.options.params) this.paramUnits(root, wanted, drawnNodes, unitOf, opened);
    return { wanted, unitOf, searchNames, boxOf };
  }

  // One edge per direction between two closed boxes (`drawn`: the unit ids) that the links
  // fetched join, as thick as the names it stands for are many; dashed while none is present.
  linkEdges(drawn, wanted) {
    const edges = new Map(); // edge id → its element
    for (const link of this.linking) {
      const [list, from, to] = link.id.split("\u0002"); // kind, group keys (overview.py's links)
      const [source, target] = [PREFIX.group + from, PREFIX.group + to];
      if (!drawn.has(source) || !drawn.has(target)) continue;
      const id = `${PREFIX.link}${from}\u0002${to}`;
      if (!edges.has(id)) edges.set(id, { kind: "link", source, target, counts: {} });
      edges.get(id).counts[list] = link.count;
    }
    const quiet = edges.size > QUIET_LINKS_ABOVE ? " quiet" : "";
    for (const [id, element] of edges) {
      const counts = Object.values(element.counts);
      const total = counts.reduce((sum, [, possible]) => sum + possible, 0);
      const present = counts.reduce((sum, [found]) => sum + found, 0);
      const label = linkRows(element).map(([count]) => count).join(" · ");
      const [from, to] = [element.source, element.target].map((unit) => drawn.get(unit));
      wanted.push({ group: "edges", classes: (present ? "" : "undetermined") + quiet,
                    data: { id, kind: "link", source: element.source, target: element.target, label,
                            width: Math.min(8, 1.2 + Math.log2(total)), element: { ...element, from, to } } });
    }
  }

  // Params as bundles: a node's own params (/ns/node/x) hang on it as one tag; the others
  // of an open group are one tag; a closed group's box counts those under it.
  paramUnits(root, wanted, drawnNodes, unitOf, opened) {
    const bundles = new Map(); // unit id → {name: where they are, params}
    const put = (unit, name, param) => {
      if (!bundles.has(unit)) bundles.set(unit, { name, params: [] });
      bundles.get(unit).params.push(param);
    };
    for (const group of [root, ...opened.values()]) {
      for (const param of group.params) {
        let owner = null;
        let name = String(param.name);
        while (!owner && name.lastIndexOf("/") > 0) {
          name = name.slice(0, name.lastIndexOf("/"));
          const units = drawnNodes.get(name);
          if (units) owner = units.find((unit) => entryFile(unit.slice(PREFIX.node.length)) === entryFile(param.id)) ?? units[0];
        }
        if (owner) put(owner, name, param);
        else put(`loose:${group.key}`, group.key ? group.label : "the workspace", param);
      }
    }
    for (const item of wanted.filter((w) => w.data.kind === "group" && w.data.params)) {
      item.data.label += ` · ${plural(item.data.params, "param")}`;
      item.data.width = widthFor(item.data.label);
    }
    for (const [owner, { name: where, params }] of bundles) {
      const loose = owner.startsWith("loose:");
      const id = `${PREFIX.params}${owner}`;
      const present = params.filter((p) => p.presence === "present").length;
      wanted.push({ group: "nodes", classes: present === params.length ? "present" : "undetermined",
                    data: { id, kind: "params", label: `${plural(params.length, "param")}${loose ? ` in ${where}` : ""}`, owner: id,
                            element: { kind: "params", name: where, params } } });
      for (const param of params) unitOf.set(param.id, id);
      if (!loose) wanted.push({ group: "edges", classes: "", data: { id: `e:${id}`, kind: "params", source: owner, target: id } });
    }
  }

  // -- drawing --------------------------------------------------------------------------------
  render(root) {
    const { wanted: list, unitOf, searchNames, boxOf } = this.plan(this.state, root);
    this.unitOf = unitOf;
    this.boxOf = boxOf;
    this.units = searchNames;
    const wanted = new Map(list.map((item) => [item.data.id, item]));
    const cy = this.cy;
    const selected = cy.$(":selected").map((element) => element.id());
    const added = [];
    let removed = 0;
    const before = new Map(cy.nodes().map((node) => [node.id(), { ...node.position() }]));
    cy.batch(() => {
      const gone = cy.elements().filter((element) => !wanted.has(element.id()));
      removed = gone.length;
      cy.remove(gone);
      for (const item of wanted.values()) {
        const element = cy.getElementById(item.data.id);
        if (element.empty()) added.push(item);
        else element.data(item.data).classes(item.classes);
      }
      cy.add(added);
      // the same ids are the same elements: keep them selected across steps
      for (const id of selected) cy.getElementById(id).select();
      this.markNear();
    });
    if (added.length || removed) this.layout(before);
    else if (!this.moved && this.layoutsDone === this.layoutRuns) this.fit(); // labels may have changed
    if (this.focused && cy.getElementById(this.focused).empty()) this.focused = null;
    this.applyVisibility();
    this.onSelect(this.selectedElement(), false);
    this.onDrawn();
  }

  // Places every unit (layered where topics connect them, a grid for the rest), then moves
  // them there from where they were (new ones from the box they came out of) and, unless the
  // user moved the view since it was last fitted, the view to the whole drawing. Links between
  // closed boxes do not place them: layered, dozens of boxes joined every which way spread
  // over several screens; on the grid they stay in one view, the links drawn across it.
  layout(before) {
    const cy = this.cy;
    const placing = cy.edges('[kind != "link"]');
    const loose = cy.nodes().filter((node) => node.connectedEdges(placing).empty());
    const layered = cy.nodes().difference(loose).union(placing);
    // the elements drawn one by one (the selected files') first, at the top left; under them
    // the part topics connect (layered), beside it (or under a wide one) the boxes
    const single = loose.filter((node) => ["node", "test", "params"].includes(node.data("kind")));
    let top = single.nonempty() ? this.grid(single, 0, 0, true) + CELL.height / 2 : 0;
    let left = 0;
    if (layered.nonempty()) {
      this.placeLayered(layered);
      const box = layered.boundingBox();
      for (const node of layered.nodes()) {
        const at = node.position();
        node.position({ x: at.x - box.x1, y: at.y - box.y1 + top });
      }
      const aspect = cy.width() / Math.max(1, cy.height());
      if (box.h * aspect > box.w) left = box.w + CELL.width / 2;
      else top += box.h + CELL.height / 2;
    }
    this.grid(loose.difference(single), left, top);
    const target = new Map(cy.nodes().map((node) => [node.id(), { ...node.position() }]));
    const drawing = cy.elements(":visible").boundingBox(); // where everything will be, labels too
    const origin = this.origin;
    this.origin = null;
    cy.batch(() => {
      for (const node of cy.nodes()) {
        const start = before.get(node.id()) ?? origin ?? target.get(node.id());
        node.position(start);
      }
    });
    cy.stop(true);
    cy.nodes().stop(true); // a layout still moving: its units start again from where they are
    const runs = ++this.layoutRuns;
    this.container.dataset.layout = "running";
    const finish = () => {
      this.settle = null;
      this.layoutsDone = runs;
      if (runs === this.layoutRuns && this.refit) {
        this.refit = false;
        if (!this.moved) this.fitNow();
      }
      if (runs === this.layoutRuns && !this.pending) this.container.dataset.layout = "done";
    };
    this.settle = finish; // called by a view that stops this one's motion of the view
    for (const node of cy.nodes()) node.animate({ position: target.get(node.id()) }, { duration: ANIMATION_MS });
    const viewport = this.moved ? { pan: cy.pan(), zoom: cy.zoom() } : this.viewportFor(drawing);
    cy.animate(viewport, { duration: ANIMATION_MS, complete: finish });
  }

  // Places the part topics connect: dagre's layers (data flowing left to right), or when a
  // view shows these larger, three layers (the units that only feed names, the names, the
  // rest), ordered by the mean place of their neighbours. Dagre's layers are as long as the
  // longest chain of names and units (boxes feeding and using dozens of names make ten) and
  // as tall as the most crowded (a node's topics and services); either way, layers are
  // wrapped into side-by-side columns, at the height that the view shows at the largest zoom.
  placeLayered(layered) {
    layered.layout(LAYERED).run();
    const byX = new Map(); // dagre centres a layer's nodes on one x
    for (const node of layered.nodes()) {
      const x = Math.round(node.position("x"));
      if (!byX.has(x)) byX.set(x, []);
      byX.get(x).push(node);
    }
    const flowing = this.wrapped([...byX.keys()].sort((a, b) => a - b)
      .map((x) => byX.get(x).sort((a, b) => a.position("y") - b.position("y"))));
    const compact = this.wrapped(this.threeLayers(layered));
    const best = compact.zoom > flowing.zoom ? compact : flowing;
    for (const [node, at] of best.places) node.position(at);
  }

  // Units feeding names only | the names | the others, each layer sorted by its neighbours'
  // mean place in the previous one (a few sweeps each way).
  threeLayers(layered) {
    const channel = (node) => CHANNELS.some(([kind]) => kind === node.data("kind"));
    const feedsOnly = (node) => node.connectedEdges().every((edge) => edge.source().same(node));
    const nodes = layered.nodes().sort((a, b) => String(a.data("label")).localeCompare(String(b.data("label"))));
    const layers = [nodes.filter((n) => !channel(n) && feedsOnly(n)), nodes.filter(channel),
                    nodes.filter((n) => !channel(n) && !feedsOnly(n))].map((layer) => [...layer]);
    const order = (layer, by) => {
      const at = new Map(by.map((node, index) => [node.id(), index]));
      const mean = new Map(layer.map((node, index) => {
        const places = node.neighborhood("node").map((n) => at.get(n.id())).filter((i) => i !== undefined);
        return [node.id(), places.length ? places.reduce((a, b) => a + b, 0) / places.length : index];
      }));
      layer.sort((a, b) => mean.get(a.id()) - mean.get(b.id()));
    };
    for (let sweep = 0; sweep < 3; sweep += 1) {
      order(layers[1], [...layers[0], ...layers[2]]);
      order(layers[0], layers[1]);
      order(layers[2], layers[1]);
    }
    return layers.filter((layer) => layer.length);
  }

  // Layers (lists of nodes, top to bottom) wrapped into columns no taller than the height at
  // which the view shows the drawing at the largest zoom: the places and that zoom.
  wrapped(layers) {
    const sizes = new Map(layers.flat().map((node) => {
      const box = node.boundingBox();
      return [node.id(), { w: box.w + LAYERED.nodeSep, h: box.h + LAYERED.nodeSep }];
    }));
    const place = (bound) => {
      const places = new Map();
      let left = 0;
      let bottom = 0;
      for (const layer of layers) {
        const columns = [[]];
        let height = 0;
        for (const node of layer) {
          const h = sizes.get(node.id()).h;
          if (height + h > bound && columns.at(-1).length) { columns.push([]); height = 0; }
          columns.at(-1).push(node);
          height += h;
        }
        for (const column of columns) {
          const width = Math.max(...column.map((node) => sizes.get(node.id()).w));
          let y = 0;
          for (const node of column) {
            const h = sizes.get(node.id()).h;
            places.set(node, { x: left + width / 2, y: y + h / 2 });
            y += h;
          }
          bottom = Math.max(bottom, y);
          left += width;
        }
        left += LAYERED.rankSep;
      }
      return { places, zoom: Math.min(this.cy.width() / left, this.cy.height() / bottom) };
    };
    const heights = [...sizes.values()].map((size) => size.h);
    const lowest = Math.max(...heights);
    const highest = heights.reduce((sum, h) => sum + h, 0);
    let best = place(highest);
    for (let step = 1; step < 25; step += 1) {
      const tried = place(lowest + ((highest - lowest) * step) / 25);
      if (tried.zoom > best.zoom) best = tried;
    }
    return best;
  }

  // Places nodes in a grid from (left, top), variants before boxes, by label; as many
  // columns as make the view's shape, no wider than the view at the lowest legible zoom.
  // Rows as wide as that (wide) for the few elements shown first. Returns the grid's bottom.
  grid(nodes, left, top, wide = false) {
    if (nodes.empty()) return top;
    const cy = this.cy;
    const rank = { node: 0, test: 0, params: 1, variants: 2, group: 3, more: 4, topic: 5, service: 5, action: 5 };
    const order = nodes.sort((a, b) => (rank[a.data("kind")] - rank[b.data("kind")])
      || String(a.data("label")).localeCompare(String(b.data("label"))));
    const aspect = cy.width() / Math.max(1, cy.height());
    const widest = Math.max(1, Math.floor((cy.width() - 2 * PADDING) / ZOOM.legible / CELL.width));
    const shaped = Math.ceil(Math.sqrt((order.length * aspect * CELL.height) / CELL.width));
    const cols = Math.max(1, Math.min(widest, wide ? order.length : shaped));
    order.forEach((node, index) => {
      node.position({ x: left + (index % cols) * CELL.width + CELL.width / 2,
                      y: top + Math.floor(index / cols) * CELL.height + CELL.height / 2 });
    });
    return top + Math.ceil(order.length / cols) * CELL.height;
  }

  // The zoom and pan that show a model bounding box whole, centred (zoomed in at most to
  // ZOOM.max: a small drawing is not blown up).
  viewportFor(box) {
    const cy = this.cy;
    if (!Number.isFinite(box.w) || box.w <= 0) return { zoom: cy.zoom(), pan: cy.pan() };
    const fitting = Math.min((cy.width() - 2 * PADDING) / box.w, (cy.height() - 2 * PADDING) / box.h);
    const zoom = Math.max(cy.minZoom(), Math.min(ZOOM.max, fitting));
    return { zoom, pan: { x: cy.width() / 2 - zoom * (box.x1 + box.x2) / 2, y: cy.height() / 2 - zoom * (box.y1 + box.y2) / 2 } };
  }

  // Moves the view to show `elements` whole; `user`: the user asked for it (a search, a
  // focus, a result), so layouts leave the view where it is until the next fit of everything.
  view(elements, user) {
    this.moved = user;
    this.cy.stop(true);
    this.settle?.(); // the layout's motion of the view was stopped: it is done all the same
    this.cy.animate(this.viewportFor(elements.boundingBox()), { duration: ANIMATION_MS });
  }

  // -- navigation -----------------------------------------------------------------------------
  search(text) {
    this.needle = text.trim().toLowerCase();
    this.applyVisibility();
  }

  // The canvas changed size (the notice above it came or went, the window was resized):
  // cytoscape learns it only from the window, so it is told here, and the view is fitted to
  // the new size unless the user moved it (a layout running fits when it ends). At once, not
  // animated: the page settling as it loads must not move what a click is aimed at.
  resized({ width, height }) {
    const before = this.size;
    this.size = { width, height };
    if (!before || (before.width === width && before.height === height)) return; // the first report
    this.cy.resize();
    if (this.moved) return;
    if (this.layoutsDone === this.layoutRuns) this.fitNow();
    else this.refit = true;
  }

  fitNow() {
    this.cy.stop(true);
    this.cy.viewport(this.viewportFor(this.cy.elements(":visible").boundingBox()));
  }

  // Fits the view to everything drawn (the Fit button); layouts fit it again from now on.
  fit() {
    this.view(this.cy.elements(":visible"), false);
  }

  // Fits the view to the search matches (Enter in the search box).
  fitMatches() {
    const matches = this.cy.nodes(".match");
    if (matches.nonempty()) this.view(matches, true);
  }

  focusSelected() {
    const selected = this.cy.$(":selected");
    if (selected.empty()) return false;
    this.focused = selected[0].id();
    this.applyVisibility();
    this.view(this.cy.elements(":visible"), true);
    return true;
  }

  showAll() {
    this.focused = null;
    this.applyVisibility();
    this.fit();
  }

  // Draws the units of the graph entries `ids` in red, for `source` (each source replaces
  // its own marks); with `fit`, the view moves to them.
  // (`groups`: the group key of each id, for those the page has not fetched).
  highlight(source, ids, groups, fit = false) {
    this.marked.set(source, ids.map((id, at) => [id, groups[at]]));
    this.applyVisibility();
    const marked = this.cy.nodes(".queried");
    if (fit && marked.nonempty()) this.view(marked, true);
  }

  // The units drawing the marked graph entries (a box, when it holds one).
  markedUnits() {
    const units = new Set();
    for (const marks of this.marked.values()) {
      for (const [id, group] of marks) {
        const unit = this.unitOf.get(id) ?? this.boxOf(group);
        if (unit) units.add(unit);
      }
    }
    return units;
  }

  applyVisibility() {
    const cy = this.cy;
    cy.batch(() => {
      cy.elements().removeClass("hidden faded match queried");
      for (const unit of this.markedUnits()) cy.getElementById(unit).addClass("queried");
      if (this.focused) {
        const centre = cy.getElementById(this.focused);
        cy.elements().difference(centre.closedNeighborhood()).addClass("hidden");
      }
      if (this.needle) {
        const matches = cy.nodes().filter((node) => (this.units.get(node.id()) ?? [])
          .some((name) => name.includes(this.needle)));
        matches.addClass("match");
        cy.elements().difference(matches).addClass("faded");
      }
    });
  }

  // Graph entry id → the id of the unit that draws it (the tests' and the console's view).
  drawing() {
    return Object.fromEntries(this.unitOf);
  }

  // What the graph shows, in graph entries (a box counts what it holds): every one that
  // is not absent.
  counts() {
    if (!this.state) return { nodes: 0, topics: 0, services: 0, params: 0, undetermined: 0, drawn: 0 };
    const root = groupTree(this.state.graph.groups);
    const nodes = root.count("nodes");
    // linked: the state counts them (a few are fetched)
    const channels = this.linked() ? this.state.channels
      : Object.fromEntries(CHANNELS.map(([kind, list]) => [list, this.channels[kind].length]));
    return { nodes, topics: channels.topics, services: channels.services + channels.actions,
             params: this.options.params ? root.count("params") : 0,
             undetermined: nodes - root.count("nodes", 0), drawn: this.cy.nodes().length };
  }
}
