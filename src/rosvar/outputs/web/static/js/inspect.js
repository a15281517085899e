// The query box and the checks panel: questions about the graph answered by the server under
// the tab's current choices (POST /api/query, POST /api/checks), asked again after every
// step. The graph entries an answer concerns are drawn in red: a query's results, or the
// finding the user clicked (each id with its group: the box drawing it when it is not
// fetched).

import { ApiError, request } from "./api.js";
import { shortPath } from "./names.js";

const TYPING_MS = 250; // a query is sent once the user pauses typing
const ASK_AFTER_MS = 300; // checks are asked for once the user pauses clicking
const PENDING_MS = 1000; // and again this often while the server lists the findings

function item(className, ...children) {
  const node = document.createElement("li");
  node.className = className;
  for (const child of children) if (child) node.append(child);
  return node;
}

function span(className, text) {
  const node = document.createElement("span");
  node.className = className;
  node.textContent = text;
  return node;
}

// "when CONDITION; e.g. FILE:ARG=VALUE ..." of a result or a finding.
function when({ presence, condition, example }) {
  const given = Object.entries(example).map(([key, value]) => `${key}=${value}`).join(" ");
  // undetermined by the choices of files alone: the element's own condition always holds
  const text = presence === "present" ? "in every configuration left"
    : condition === "true" ? "when its launch file is launched" : `when ${condition}`;
  return span("when", `${text}${given && presence !== "present" ? `; e.g. ${given}` : ""}`);
}

function place(file, line) {
  return file ? span("where", `${shortPath(file)}:${line}`) : null;
}

// Answers only the latest question: an answer to an earlier one arriving late is dropped.
class Latest {
  constructor() { this.asked = 0; }
  async ask(path, body) {
    const mine = ++this.asked;
    const answer = await request("POST", path, body);
    return mine === this.asked ? answer : null;
  }
}

export class QueryBox {
  // elements: {input, status, list}; session(): the tab's session id; graph: a GraphView.
  constructor(elements, session, graph) {
    Object.assign(this, elements);
    this.session = session;
    this.graph = graph;
    this.latest = new Latest();
    this.timer = null;
    this.input.addEventListener("input", () => {
      clearTimeout(this.timer);
      this.timer = setTimeout(() => this.update(), TYPING_MS);
    });
    this.input.addEventListener("keydown", (event) => {
      if (event.key === "Enter") { clearTimeout(this.timer); this.update(); }
    });
  }

  async update() {
    const expression = this.input.value.trim();
    this.input.classList.remove("invalid");
    if (!expression || !this.session()) {
      this.latest.asked += 1;
      this.show([], "");
      return;
    }
    try {
      const answer = await this.latest.ask("/api/query", { session: this.session(), expression });
      if (answer === null) return;
      const count = answer.total;
      const listed = count > answer.results.length ? ` (the first ${answer.results.length} listed)` : "";
      this.show(answer.results, `${count} result${count === 1 ? "" : "s"}${listed}`);
    } catch (error) {
      if (!(error instanceof ApiError) || error.status !== 400) throw error;
      this.input.classList.add("invalid");
      this.show([], error.message);
    }
    document.body.dataset.query = String(Number(document.body.dataset.query ?? 0) + 1);
  }

  show(results, status) {
    this.status.textContent = status;
    this.list.hidden = results.length === 0;
    this.list.replaceChildren(...results.map((result) => {
      const row = item("result", span("kind", result.kind), span("name", result.name),
                       span("file", shortPath(result.launch_file)), when(result),
                       place(result.file, result.line));
      row.addEventListener("click", () => this.graph.highlight("query", result.ids, result.groups, true));
      return row;
    }));
    this.graph.highlight("query", results.flatMap((result) => result.ids), results.flatMap((result) => result.groups));
  }
}

export class ChecksPanel {
  // elements: {toggle, count, panel, list}; session(): the tab's session id; state(): the
  // state shown; graph: a GraphView; failed(error): told when the server could not answer.
  constructor(elements, session, state, graph, failed) {
    Object.assign(this, elements);
    this.session = session;
    this.state = state;
    this.graph = graph;
    this.failed = failed;
    this.latest = new Latest();
    this.timer = null;
    this.chosen = null; // the key of the finding whose elements are drawn in red
    this.toggle.addEventListener("click", () => {
      this.panel.hidden = !this.panel.hidden;
      this.toggle.setAttribute("aria-expanded", String(!this.panel.hidden));
    });
  }

  // A new state: the counts of the one before are gone at once, and the server is asked once
  // the user pauses (a click never waits behind the checks of the state before).
  update() {
    clearTimeout(this.timer);
    this.latest.asked += 1; // an answer on its way is for an earlier state
    this.count.textContent = "…";
    this.count.title = "checking the current choices";
    this.list.classList.add("stale"); // the findings of the state before, until the answer
    this.timer = setTimeout(() => this.ask().catch(this.failed), ASK_AFTER_MS);
  }

  // A step is being answered: no question until its state (update), for the engine would
  // answer it first, before the step's own requests (one in flight cannot be called back).
  hold() {
    clearTimeout(this.timer);
    this.latest.asked += 1;
  }

  async ask() {
    if (!this.session()) return;
    const asked = JSON.stringify(this.state().choices);
    const answer = await this.latest.ask("/api/checks", { session: this.session() });
    // an answer for other choices than those shown (a step came meanwhile) is not shown
    if (answer === null || JSON.stringify(answer.choices) !== asked) return;
    if (asked !== JSON.stringify(this.state().choices)) return;
    if (answer.pending) { // the findings are still being listed: ask again soon
      const [done, files] = answer.pending;
      this.count.textContent = `listing… ${Math.floor((100 * done) / Math.max(1, files))} %`;
      this.count.title = `the checks have read ${done} of ${files} launch files`;
      this.timer = setTimeout(() => this.ask().catch(this.failed), PENDING_MS);
      return;
    }
    const { error = 0, warning = 0, note = 0 } = answer.counts;
    this.count.textContent = `${error} errors · ${warning} warnings · ${note} notes`;
    this.count.title = "";
    this.list.classList.remove("stale");
    const keyOf = (finding) => `${finding.check} ${finding.name} ${JSON.stringify(finding.locations)}`;
    let chosen = null;
    this.list.replaceChildren(...answer.findings.map((finding) => {
      const [first] = finding.locations;
      const row = item(`finding ${finding.severity}`, span("severity", finding.severity),
                       span("check", finding.check), span("message", finding.message),
                       when(finding), place(first.file, first.line));
      row.dataset.key = keyOf(finding);
      row.title = `${finding.message}\nlaunched by ${finding.launch_file}`;
      if (row.dataset.key === this.chosen) { row.classList.add("chosen"); chosen = finding; }
      row.addEventListener("click", () => this.choose(row, finding));
      return row;
    }));
    const more = answer.total - answer.findings.length;
    if (more > 0) this.list.append(item("finding more", span("message", `… ${more} more: rosvar check lists them all`)));
    if (this.chosen && !chosen) this.chosen = null;
    this.graph.highlight("check", chosen ? chosen.ids : [], chosen ? chosen.groups : []);
    document.body.dataset.checks = String(Number(document.body.dataset.checks ?? 0) + 1);
  }

  // A click on a finding draws its elements in red (a second click forgets it).
  choose(row, finding) {
    const again = this.chosen === row.dataset.key;
    for (const other of this.list.querySelectorAll(".chosen")) other.classList.remove("chosen");
    this.chosen = again ? null : row.dataset.key;
    if (!again) row.classList.add("chosen");
    this.graph.highlight("check", again ? [] : finding.ids, again ? [] : finding.groups, !again);
  }
}
