// The computation graph: ROS nodes (and test nodes), the topics they are wired to and (on
// request) params, drawn with Cytoscape.js and a layered (dagre) layout.
//
// Graph ids are stable across steps, so a new state only restyles the elements that changed
// (present/undetermined, conflicts) and removes the ones that became absent (absent elements
// are not drawn); the layout runs again only when elements appear.

cytoscape.use(cytoscapeDagre);

// Connected elements get the layered layout; launch files declare few topics, so most nodes
// have no edge and would stack in one rank: they go to a grid under the layered part instead.
// Namespace boxes are packed by Cytoscape's force-directed layout (it handles compounds).
const LAYERED = { name: "dagre", rankDir: "LR", nodeSep: 14, rankSep: 70, animate: false, fit: false };
const GROUPED = { name: "cose", animate: false, fit: false, nodeDimensionsIncludeLabels: true, randomize: false };
const CELL = { width: 150, height: 56 };

const STYLE = [
  { selector: "node", style: {
    label: "data(label)", "font-size": 11, "text-valign": "bottom", "text-margin-y": 3,
    "min-zoomed-font-size": 7, "text-wrap": "ellipsis", "text-max-width": 180,
    "border-width": 1.5, "border-color": "#333",
  } },
  { selector: 'node[kind = "node"]', style: { shape: "ellipse", "background-color": "#fff", width: 28, height: 28 } },
  { selector: 'node[kind = "test"]', style: { shape: "ellipse", "background-color": "#fff", "border-style": "double", "border-width": 4, width: 28, height: 28 } },
  { selector: 'node[kind = "topic"]', style: { shape: "round-rectangle", "background-color": "#8ecae6", width: 24, height: 14 } },
  { selector: 'node[kind = "param"]', style: { shape: "tag", "background-color": "#ffd166", width: 18, height: 12 } },
  { selector: 'node[kind = "namespace"]', style: {
    shape: "round-rectangle", "background-color": "#f3f5f9", "border-style": "dotted",
    "border-color": "#9aa3b5", "text-valign": "top", "text-margin-y": -2, "font-weight": "bold",
    padding: 14,
  } },
  { selector: "edge", style: { width: 1.2, "line-color": "#9aa3b5", "curve-style": "bezier" } },
  { selector: ".undetermined", style: { "border-style": "dashed", "line-style": "dashed", "background-opacity": 0.7 } },
  { selector: "node.conflict", style: { "border-color": "#b42318", "border-width": 4, color: "#b42318" } },
  { selector: "node.match", style: { "border-color": "#2f6fdb", "border-width": 4 } },
  { selector: ":selected", style: { "overlay-color": "#2f6fdb", "overlay-opacity": 0.18, "overlay-padding": 5 } },
  { selector: ".faded", style: { opacity: 0.15 } },
  { selector: ".hidden", style: { display: "none" } },
];

const PREFIX = { node: "n:", test: "n:", topic: "t:", param: "p:", namespace: "ns:" };

function namespaceOf(name) {
  const cut = String(name).lastIndexOf("/");
  return cut > 0 ? String(name).slice(0, cut + 1) : "/";
}

function lastSegment(name) {
  const text = String(name).replace(/\/$/, "");
  return text.slice(text.lastIndexOf("/") + 1) || text;
}

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

export class GraphView {
  // onSelect(element | null) is called with the selected element's JSON (plus its kind)
  // whenever the selection or the selected element's data changes.
  constructor(container, onSelect) {
    this.cy = cytoscape({ container, style: STYLE, minZoom: 0.05, maxZoom: 4, boxSelectionEnabled: false });
    this.options = { params: false, groups: false };
    this.focused = null; // element id whose neighbourhood alone is shown
    this.needle = "";
    this.state = null;
    this.onSelect = onSelect;
    this.cy.on("select unselect", () => this.notifySelection());
  }

  selectedElement() {
    const selected = this.cy.$(":selected");
    return selected.nonempty() ? selected[0].data("element") ?? null : null;
  }

  notifySelection() {
    this.onSelect(this.selectedElement());
  }

  // changes: what changed since the last update (delta.js touched), null for everything.
  update(state, changes = null) {
    this.state = state;
    if (changes === null || changes.fields.has("conflicts")) this.render();
    else if (changes.graph.size) this.render(changes.graph);
  }

  setOption(name, value) {
    this.options[name] = value;
    this.render();
  }

  // -- elements -------------------------------------------------------------------------------
  elements(graph, conflicts) {
    const clashing = conflictNames(conflicts);
    const wanted = [];
    const namespaces = new Set();
    const group = (name) => {
      if (!this.options.groups) return undefined;
      const ns = namespaceOf(name);
      if (ns === "/") return undefined;
      namespaces.add(ns);
      return PREFIX.namespace + ns;
    };
    // data.owner: the id of the graph entry the Cytoscape element is drawn for
    const add = (kind, item, label, classes) => {
      const data = { id: PREFIX[kind] + item.id, owner: item.id, kind, label, element: { kind, ...item } };
      const parent = group(item.name);
      if (parent) data.parent = parent;
      wanted.push({ group: "nodes", data, classes: [item.presence, ...classes].join(" ") });
    };
    const visible = (item) => item.presence !== "absent";
    const nodeIds = new Map(); // ROS node name → element ids (variants share a name)
    const shown = new Set();
    const nodes = [["node", graph.nodes], ["test", graph.tests ?? []]];
    for (const [kind, node] of nodes.flatMap(([k, list]) => list.filter(visible).map((n) => [k, n]))) {
      const clash = clashing.has(clashName(kind, node.name));
      const name = this.options.groups ? lastSegment(node.name) : node.name;
      add(kind, node, clash ? `⚠ ${name}` : name, clash ? ["conflict"] : []);
      if (!nodeIds.has(node.name)) nodeIds.set(node.name, []);
      nodeIds.get(node.name).push(node.id);
      shown.add(node.id);
    }
    for (const topic of graph.topics.filter(visible)) {
      add("topic", topic, this.options.groups ? lastSegment(topic.name) : topic.name, []);
      for (const nodeId of topic.nodes.filter((id) => shown.has(id))) {
        const undetermined = topic.presence === "undetermined" ? "undetermined" : "";
        wanted.push({ group: "edges", classes: undetermined,
                      data: { id: `e:${topic.id}:${nodeId}`, owner: topic.id, source: PREFIX.node + nodeId, target: PREFIX.topic + topic.id } });
      }
    }
    if (this.options.params) {
      for (const param of graph.params.filter(visible)) {
        const clash = clashing.has(clashName("param", param.name));
        const name = this.options.groups ? lastSegment(param.name) : param.name;
        add("param", param, clash ? `⚠ ${name}` : name, clash ? ["conflict"] : []);
        // a private param (/ns/node/x) hangs on its node
        for (const [nodeName, ids] of nodeIds) {
          if (!String(param.name).startsWith(`${nodeName}/`)) continue;
          for (const nodeId of ids) {
            wanted.push({ group: "edges", classes: param.presence === "undetermined" ? "undetermined" : "",
                          data: { id: `e:${param.id}:${nodeId}`, owner: param.id, source: PREFIX.node + nodeId, target: PREFIX.param + param.id } });
          }
        }
      }
    }
    for (const ns of namespaces) {
      // nested namespaces nest their boxes: /a/b/ inside /a/
      const outer = namespaceOf(ns.slice(0, -1));
      const data = { id: PREFIX.namespace + ns, kind: "namespace", label: ns,
                     element: { kind: "namespace", name: ns } };
      if (outer !== "/") {
        data.parent = PREFIX.namespace + outer;
        namespaces.add(outer); // visited later by this same loop
      }
      wanted.unshift({ group: "nodes", data, classes: "" });
    }
    return wanted;
  }

  // changed: ids of the graph entries that changed (null: any may have). Elements that are
  // no longer wanted are removed and the others keep their places; the layout runs again
  // only when elements are added.
  render(changed = null) {
    if (!this.state) return;
    const wanted = new Map(this.elements(this.state.graph, this.state.conflicts).map((item) => [item.data.id, item]));
    const cy = this.cy;
    const selected = cy.$(":selected").map((element) => element.id());
    const added = [];
    cy.batch(() => {
      // gone, or moved into another namespace box (drawn again below)
      cy.remove(cy.elements().filter((element) => {
        const item = wanted.get(element.id());
        return !item || item.data.parent !== element.data("parent");
      }));
      for (const item of wanted.values()) {
        const element = cy.getElementById(item.data.id);
        if (element.empty()) added.push(item);
        else if (!changed || changed.has(item.data.owner)) element.data(item.data).classes(item.classes);
      }
      cy.add(added);
      // the same ids are the same elements: keep them selected across steps
      for (const id of selected) cy.getElementById(id).select();
    });
    if (added.length) this.layout();
    if (this.focused && cy.getElementById(this.focused).empty()) this.focused = null;
    this.applyVisibility();
    this.notifySelection();
  }

  layout() {
    const cy = this.cy;
    if (this.options.groups) {
      cy.layout(GROUPED).run();
    } else {
      const loose = cy.nodes().filter((node) => node.degree(false) === 0);
      const layered = cy.elements().difference(loose);
      let top = 0;
      let left = 0;
      if (layered.nonempty()) {
        layered.layout(LAYERED).run();
        const box = layered.boundingBox();
        top = box.y2 + CELL.height;
        left = box.x1;
      }
      if (loose.nonempty()) {
        // as many columns as make the grid's shape the view's
        const aspect = cy.width() / Math.max(1, cy.height());
        const cols = Math.ceil(Math.sqrt((loose.length * aspect * CELL.height) / CELL.width));
        const rows = Math.ceil(loose.length / cols);
        loose.layout({
          name: "grid", fit: false, cols, avoidOverlap: true,
          boundingBox: { x1: left, y1: top, w: cols * CELL.width, h: rows * CELL.height },
          sort: (a, b) => String(a.data("label")).localeCompare(String(b.data("label"))),
        }).run();
      }
    }
    cy.fit(cy.elements(), 30);
  }

  // -- navigation -----------------------------------------------------------------------------
  search(text) {
    this.needle = text.trim().toLowerCase();
    this.applyVisibility();
  }

  // Fit the view to the search matches (or everything).
  fit() {
    const matches = this.cy.nodes(".match");
    this.cy.fit(matches.nonempty() ? matches : this.cy.elements(":visible"), 30);
  }

  focusSelected() {
    const selected = this.cy.$(":selected");
    if (selected.empty()) return false;
    this.focused = selected[0].id();
    this.applyVisibility();
    this.cy.fit(this.cy.elements(":visible"), 30);
    return true;
  }

  showAll() {
    this.focused = null;
    this.applyVisibility();
    this.fit();
  }

  applyVisibility() {
    const cy = this.cy;
    cy.batch(() => {
      cy.elements().removeClass("hidden faded match");
      if (this.focused) {
        const centre = cy.getElementById(this.focused);
        const keep = centre.closedNeighborhood().union(centre.closedNeighborhood().ancestors());
        cy.elements().difference(keep).addClass("hidden");
      }
      if (this.needle) {
        const matches = cy.nodes().filter((node) => node.data("kind") !== "namespace"
          && String(node.data("label")).toLowerCase().includes(this.needle));
        matches.addClass("match");
        cy.elements().difference(matches.union(matches.ancestors())).addClass("faded");
      }
    });
  }

  counts() {
    const visible = this.cy.nodes(":visible");
    const of = (kind) => visible.filter(`[kind = "${kind}"]`).length;
    const undetermined = visible.filter(".undetermined").length;
    return { nodes: of("node"), topics: of("topic"), params: of("param"), undetermined };
  }
}
