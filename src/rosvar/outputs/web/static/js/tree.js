// The feature tree: packages → launch files → args → values.
//
// The features of a workspace never change while the server runs, so the tree's elements are
// built once (build) and every new state only updates marks, buttons and warnings (update):
// what the user opened, typed or scrolled stays as it was.

import { packageOf } from "./names.js";

const OTHER = "<other>";
const DEFAULT = /^<default: (.*)>$/s;

const MARKS = {
  selected: ["✓", "(✓)"],
  deselected: ["✗", "(✗)"],
  unselected: ["·", "·"],
};

// How a value reads: "<default: $(find x)/a>" is the default's text, unevaluated; "<unset>"
// an arg given no value.
function valueText(value) {
  const match = DEFAULT.exec(value);
  if (match) return match[1];
  return value === "<unset>" ? "(no value)" : value;
}

// A value feature naming a literal value (not <other>, not <default: TEXT>).
function isLiteral(feature) {
  return feature.kind === "value" && !feature.value.startsWith("<");
}

function element(tag, attributes = {}, ...children) {
  const node = document.createElement(tag);
  for (const [name, value] of Object.entries(attributes)) {
    if (name === "class") node.className = value;
    else if (name === "text") node.textContent = value;
    else node.setAttribute(name, value);
  }
  node.append(...children);
  return node;
}

// A file's path below its package's folder; a package named apart from its folder (ROS 2's
// ros2_control_demo_example_2 in example_2/) shows the path from its launch/ folder.
function fileLabel(id, pkg) {
  const at = id.lastIndexOf(`${pkg}/`);
  if (at === 0 || (at > 0 && id[at - 1] === "/")) return id.slice(at + pkg.length + 1);
  const parts = id.split("/");
  const launch = parts.lastIndexOf("launch");
  return launch >= 0 && launch < parts.length - 1 ? parts.slice(launch).join("/") : parts[parts.length - 1];
}

function chooseButtons() {
  return element("span", { class: "choose" },
    element("button", { type: "button", "data-action": "select", title: "select", text: "✓" }),
    element("button", { type: "button", "data-action": "deselect", title: "deselect", text: "✗" }));
}

export class FeatureTree {
  // onChoose(action, featureId, value?) is called for every click or typed value.
  constructor(container, popup, onChoose) {
    this.container = container;
    this.popup = popup;
    this.onChoose = onChoose;
    this.rows = new Map(); // feature id → its element (carries the state classes)
    this.files = new Map(); // file id → {element, warn, pkg}
    this.others = new Map(); // arg id → the text input of its <other> slot
    this.packages = [];
    this.state = null;
    container.addEventListener("click", (event) => this.clicked(event));
    container.addEventListener("keydown", (event) => this.typed(event));
    // the conflicts popup closes on a click elsewhere or on Escape
    document.addEventListener("click", (event) => {
      if (!popup.hidden && !popup.contains(event.target) && !event.target.closest(".warn")) {
        popup.hidden = true;
      }
    });
    document.addEventListener("keydown", (event) => { if (event.key === "Escape") popup.hidden = true; });
  }

  // defaults: arg id → the id of its default value.
  build(features, defaults = {}) {
    this.defaults = new Set(Object.values(defaults));
    this.defaultOf = defaults;
    const children = new Map();
    for (const [id, feature] of Object.entries(features)) {
      const key = feature.parent ?? "";
      if (!children.has(key)) children.set(key, []);
      children.get(key).push([id, feature]);
    }
    const byPackage = new Map();
    for (const [id, feature] of children.get("") ?? []) {
      const pkg = packageOf(feature);
      if (!byPackage.has(pkg)) byPackage.set(pkg, []);
      byPackage.get(pkg).push([id, feature]);
    }
    this.container.replaceChildren();
    for (const pkg of [...byPackage.keys()].sort()) {
      const files = byPackage.get(pkg);
      const count = element("span", { class: "hint" });
      const node = element("details", { class: "package", open: "" },
        element("summary", {}, `${pkg} `, count));
      for (const [id, feature] of files) node.append(this.fileNode(id, feature, pkg, children));
      this.packages.push({ element: node, count, files: files.map(([id]) => id) });
      this.container.append(node);
    }
  }

  fileNode(id, feature, pkg, children) {
    const warn = element("button", { type: "button", class: "warn", title: "conflicts", text: "⚠" });
    warn.hidden = true;
    const summary = element("summary", { class: "row" },
      element("span", { class: "mark" }),
      element("span", { class: "name", title: id, text: fileLabel(id, pkg) }),
      warn, chooseButtons());
    const node = element("details", { class: "feature file", "data-id": id }, summary);
    const args = children.get(id) ?? [];
    if (!args.length) node.classList.add("leaf");
    for (const [argId, arg] of args) node.append(this.argNode(argId, arg, children));
    this.rows.set(id, node);
    this.files.set(id, { element: node, warn, pkg });
    return node;
  }

  argNode(id, feature, children) {
    const fallback = this.defaultOf[id];
    const hint = fallback ? `default: ${valueText(fallback.slice(id.length + 1))}` : "";
    const values = element("ul", { class: "values" });
    const node = element("details", { class: "feature arg", "data-id": id },
      element("summary", { class: "row" },
        element("span", { class: "mark" }),
        element("span", { class: "name", title: feature.doc ? `${feature.arg}: ${feature.doc}` : id, text: feature.arg }),
        element("span", { class: "hint", text: hint, title: hint }),
        chooseButtons()),
      feature.doc ? element("p", { class: "doc", text: feature.doc }) : "",
      values);
    for (const [valueId, value] of children.get(id) ?? []) {
      values.append(value.value === OTHER ? this.otherNode(valueId, id) : this.valueNode(valueId, value));
    }
    this.rows.set(id, node);
    return node;
  }

  // A value, whole (long ones wrap); the arg's default is badged, an unevaluated default
  // reads as its text.
  valueNode(id, feature) {
    const isDefault = this.defaults.has(id);
    const text = valueText(feature.value);
    const node = element("li", { class: `feature value${isDefault ? " default" : ""}`, "data-id": id },
      element("div", { class: "row" },
        element("span", { class: "mark" }),
        element("span", { class: "name", title: isDefault ? `${text} (the default)` : text }, element("code", { text })),
        isDefault ? element("span", { class: "badge default-badge", text: "default" }) : "",
        chooseButtons()));
    this.rows.set(id, node);
    return node;
  }

  // The <other> slot: any text the user types (set FILE:ARG=TEXT), or deselected as a whole.
  otherNode(id, argId) {
    const input = element("input", { type: "text", placeholder: "other value…",
                                     "aria-label": `other value of ${argId}`, "data-arg": argId });
    const node = element("li", { class: "feature value other", "data-id": id },
      element("div", { class: "row" },
        element("span", { class: "mark" }), input,
        element("button", { type: "button", class: "set", "data-arg": argId, text: "Set" }),
        element("span", { class: "choose" },
          element("button", { type: "button", "data-action": "deselect", title: "no other value", text: "✗" }))));
    this.rows.set(id, node);
    this.others.set(argId, input);
    return node;
  }

  // -- events ---------------------------------------------------------------------------------
  clicked(event) {
    const target = event.target;
    const button = target.closest("button");
    if (!button) return;
    event.preventDefault(); // a button inside <summary> must not also fold the row
    if (button.classList.contains("warn")) {
      this.showConflicts(button.closest(".file").dataset.id, button);
    } else if (button.classList.contains("set")) {
      this.setOther(button.dataset.arg);
    } else if (button.dataset.action) {
      const id = button.closest(".feature").dataset.id;
      const feature = this.state.features[id];
      const mine = !feature.derived && feature.state === `${button.dataset.action}ed`;
      if (mine) this.onChoose("unselect", id);
      else if (button.dataset.action === "select" && isLiteral(feature)) {
        // "set" replaces the arg's earlier value, as a radio button would
        this.onChoose("set", feature.parent, feature.value);
      } else this.onChoose(button.dataset.action, id);
    }
  }

  typed(event) {
    if (event.key === "Enter" && event.target.dataset.arg) {
      event.preventDefault();
      this.setOther(event.target.dataset.arg);
    }
  }

  setOther(argId) {
    const text = this.others.get(argId).value;
    if (text !== "") this.onChoose("set", argId, text);
  }

  // -- state ----------------------------------------------------------------------------------
  // changed: the ids of the features that changed since the last update (null: all of them).
  update(state, changed = null) {
    this.state = state;
    for (const id of changed ?? this.rows.keys()) {
      const node = this.rows.get(id);
      const feature = state.features[id];
      node.classList.remove("selected", "deselected", "unselected", "derived");
      node.classList.add(feature.state);
      if (feature.derived) node.classList.add("derived");
      const mark = node.querySelector(".mark");
      mark.textContent = MARKS[feature.state][feature.derived ? 1 : 0];
      mark.title = `${feature.state}${feature.derived ? " (derived)" : ""}`;
      for (const button of node.querySelector(".choose").children) {
        button.classList.toggle("on", !feature.derived && feature.state === `${button.dataset.action}ed`);
      }
    }
    this.showTyped(state);
    this.showWarnings(state.conflicts);
    for (const pkg of this.packages) {
      const chosen = pkg.files.filter((id) => state.features[id].state === "selected").length;
      pkg.count.textContent = `${pkg.files.length} files${chosen ? `, ${chosen} selected` : ""}`;
    }
  }

  // The text of an accepted "set" that went to an <other> slot, shown in its input; an
  // <other> slot selected without a text yet asks for one.
  showTyped(state) {
    const typed = new Map();
    for (const choice of state.choices ?? []) {
      if (choice.action === "set") typed.set(choice.feature, choice.value);
    }
    const untyped = new Set(state.untyped ?? []);
    for (const [argId, input] of this.others) {
      input.classList.toggle("needs-text", untyped.has(argId));
      if (document.activeElement === input) continue;
      const text = typed.get(argId);
      const other = state.features[`${argId}=${OTHER}`];
      input.value = text !== undefined && other && other.state === "selected" ? text : "";
    }
  }

  conflictsOf(fileId) {
    return (this.state?.conflicts ?? []).filter((conflict) => conflict.files.includes(fileId));
  }

  showWarnings(conflicts) {
    const worst = new Map();
    for (const conflict of conflicts) {
      for (const file of conflict.files) {
        if (worst.get(file) !== "certain") worst.set(file, conflict.status);
      }
    }
    for (const [id, file] of this.files) {
      const status = worst.get(id);
      file.warn.hidden = status === undefined;
      file.warn.className = `warn ${status ?? ""}`;
      file.warn.title = status ? `${status} conflict — click for details` : "";
    }
  }

  showConflicts(fileId, anchor) {
    const items = this.conflictsOf(fileId).map((conflict) => {
      const others = conflict.files.filter((file) => file !== fileId);
      const where = others.length ? others.join(", ") : "itself";
      const when = conflict.status === "certain" ? "always, in every remaining configuration"
        : `when ${conflict.condition ?? "some choices hold"}`;
      return element("li", {},
        element("span", { class: `status-${conflict.status}`, text: conflict.status }),
        ` with ${where}: ${conflict.names.join(", ")} — ${when}`);
    });
    this.popup.replaceChildren(element("h2", { text: `⚠ Conflicts of ${fileId}` }), element("ul", {}, ...items));
    const top = anchor.getBoundingClientRect().bottom - this.popup.parentElement.getBoundingClientRect().top;
    this.popup.style.top = `${top + 4}px`;
    this.popup.hidden = false;
  }

  // -- navigation -----------------------------------------------------------------------------
  filter(text) {
    const needle = text.trim().toLowerCase();
    for (const pkg of this.packages) {
      let shown = 0;
      for (const id of pkg.files) {
        const hide = needle !== "" && !id.toLowerCase().includes(needle);
        this.files.get(id).element.classList.toggle("hidden-by-filter", hide);
        if (!hide) shown += 1;
      }
      pkg.element.classList.toggle("hidden-by-filter", shown === 0);
      if (needle && shown) pkg.element.open = true;
    }
  }

  expand(open) {
    for (const node of this.container.querySelectorAll(open ? ".package" : "details")) node.open = open;
  }
}
