// Wires the page: every user action goes to the server, and every state it answers updates
// the tree, the graph (with the members of its open groups fetched again), the details and
// the bar at once (the tree only where the answer says something changed). A choice made
// while the previous one is still being answered is ignored (a double click is one choice);
// the steps the page makes itself run one after another.

import { ApiError, Client, waiting } from "./api.js";
import { Bar } from "./bar.js";
import { DetailsPanel } from "./details.js";
import { GraphView } from "./graph.js";
import { ChecksPanel, QueryBox } from "./inspect.js";
import { FeatureTree } from "./tree.js";

const $ = (id) => document.getElementById(id);

const client = new Client(() => $("group-by").value);
let state = null;
let queue = Promise.resolve();

const bar = new Bar(
  {
    featuresLeft: $("features-left"), configurations: $("configurations"), completeness: $("completeness"),
    undo: $("undo"), redo: $("redo"), reset: $("reset"), finish: $("finish"),
    message: $("message"), command: $("command"), copy: $("copy"), status: $("command-status"),
    notice: $("notice"), noticeText: $("notice-text"), noticeClose: $("notice-close"),
  },
  {
    undo: () => choose(() => client.undo()),
    redo: () => choose(() => client.redo()),
    reset: () => choose(() => client.reset()),
    finish: () => choose(() => client.finish()),
  },
);
const tree = new FeatureTree($("tree"), $("conflict-popup"), (action, feature, value) => {
  choose(() => client.choose(action, feature, value));
});
const graph = new GraphView($("graph"), (group, kind, page) => client.members(group, kind, page), (groups) => client.links(groups), (element, byUser) => {
  // a new selection opens the details; a step only refreshes them if they are open
  if (byUser || details.shown !== null) details.show(element, state);
  $("focus").disabled = !element;
}, () => showCounts());
const details = new DetailsPanel($("details"), $("details-body"), $("details-close"), {
  open: (unitId) => graph.open(unitId),
  close: (groupKey) => graph.close(groupKey),
  unselect: () => graph.cy.$(":selected").unselect(),
});

const session = () => client.session;
const query = new QueryBox({ input: $("query"), status: $("query-status"), list: $("query-results") }, session, graph);
const checks = new ChecksPanel({ toggle: $("checks-toggle"), count: $("checks-count"), panel: $("checks"), list: $("checks-list") },
                               session, () => state, graph, (error) => bar.say(`Checks: ${error.message}`, true));

// changes: what changed since the state rendered before (Client.receive), null for all.
async function render(next, changes = null) {
  state = next;
  tree.update(state, changes?.features ?? null);
  bar.update(state);
  await graph.update(state);
  query.update().catch((error) => bar.say(`Query: ${error.message}`, true));
  checks.update();
  // body[data-step] counts rendered states: tests (and curious users) can wait for the next one
  document.body.dataset.step = String(Number(document.body.dataset.step ?? 0) + 1);
}

function showCounts() {
  const counts = graph.counts();
  $("graph-counts").textContent = `${counts.nodes} nodes · ${counts.topics} topics · ${counts.services} services/actions`
    + (graph.options.params ? ` · ${counts.params} params` : "") + ` · ${counts.undetermined} undetermined`
    + ` · drawn as ${counts.drawn}`;
}

// A user's step: dropped while another is being answered (no double choices).
let pending = 0;
function choose(call) {
  if (pending) return queue;
  return act(call);
}

// Runs one server call after the previous one, then renders its answer.
function act(call) {
  pending += 1;
  queue = queue.then(async () => {
    document.body.classList.add("busy");
    bar.say("");
    bar.dismiss();
    checks.hold();
    try {
      const answer = await call();
      await render(answer.state, answer.changes);
    } catch (error) {
      if (error instanceof ApiError && error.status === 404) {
        await render((await client.open()).state); // the server forgot this tab's session
        bar.say("Your session had expired: started over.", true);
      } else {
        bar.say(`Error: ${error.message}`, true);
        checks.update(); // the state shown is still the one before: its checks are asked again
      }
    } finally {
      pending -= 1;
      document.body.classList.remove("busy");
    }
  });
  return queue;
}

waiting.addEventListener("wait", () => bar.say("Waiting for the server: it is computing another client's step…"));

function wireToolbars() {
  $("tree-filter").addEventListener("input", (event) => tree.filter(event.target.value));
  $("expand-all").addEventListener("click", () => tree.expand(true));
  $("collapse-all").addEventListener("click", () => tree.expand(false));
  $("graph-search").addEventListener("input", (event) => graph.search(event.target.value));
  $("graph-search").addEventListener("keydown", (event) => { if (event.key === "Enter") graph.fitMatches(); });
  $("show-params").addEventListener("change", (event) => { graph.setOption("params", event.target.checked); });
  $("group-by").addEventListener("change", () => act(() => client.regroup()));
  $("overview").addEventListener("click", () => graph.overview());
  $("fit").addEventListener("click", () => graph.fit());
  $("focus").addEventListener("click", () => { $("show-all").disabled = !graph.focusSelected(); });
  $("show-all").addEventListener("click", () => { graph.showAll(); $("show-all").disabled = true; });
  document.addEventListener("keydown", (event) => {
    if (!(event.ctrlKey || event.metaKey) || event.key.toLowerCase() !== "z") return;
    if (event.target.matches("input")) return;
    event.preventDefault();
    if (event.shiftKey ? state.can_redo : state.can_undo) choose(() => (event.shiftKey ? client.redo() : client.undo()));
  });
}

async function start() {
  wireToolbars();
  try {
    const { state: first } = await client.start();
    tree.build(first.features, client.catalog.defaults);
    await render(first);
  } catch (error) {
    bar.say(`Cannot reach the rosvar server: ${error.message}`, true);
  }
}

// A handle for the browser console and the end-to-end tests.
window.rosvar = { graph, tree, act, details, query, checks, get state() { return state; } };

start();
