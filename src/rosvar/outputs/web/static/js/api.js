// The server's JSON API, with one configuration session per browser tab.
//
// The session is in overview mode (docs/web.md): its states carry the features as one
// character each (read through the catalog, fetched once) and the graph as group summaries;
// the graph view fetches a group's members when it draws them. The client holds the tab's
// state and sends its version with every step: the server then answers with what changed
// only (delta.js), which the client applies.
//
// The session id lives in sessionStorage, which belongs to one tab. A duplicated tab starts
// with a copy of it, so at start-up a tab asks the others (BroadcastChannel) whether one of
// them already holds its id, and opens a fresh session if so: two tabs never share choices.

import { Catalog } from "./catalog.js";
import { patch } from "./delta.js";

const KEY = "rosvar.session";
const CHANNEL = "rosvar.sessions";
const CLAIM_WAIT_MS = 150;

export class ApiError extends Error {
  constructor(status, message) {
    super(message);
    this.status = status;
  }
}

// Told while a request waits for the engine, busy with another client's step: its
// "wait" events carry the server's message (the page says it).
export const waiting = new EventTarget();
const BUSY = 503;
const BUSY_TRIES = 30;

export async function request(method, path, body) {
  const options = { method, headers: {} };
  if (body !== undefined) {
    options.headers["Content-Type"] = "application/json";
    options.body = JSON.stringify(body);
  }
  for (let tries = 1; ; tries += 1) {
    const response = await fetch(path, options);
    const document = await response.json();
    if (response.ok) return document;
    if (response.status !== BUSY || tries === BUSY_TRIES) {
      throw new ApiError(response.status, document.error || response.statusText);
    }
    waiting.dispatchEvent(new CustomEvent("wait", { detail: document.error }));
    const seconds = Number(response.headers.get("Retry-After")) || 1;
    await new Promise((resolve) => setTimeout(resolve, seconds * 1000));
  }
}

// Resolves true when another open tab answers that it owns `id`.
function claimedElsewhere(channel, id) {
  return new Promise((resolve) => {
    const timer = setTimeout(() => { channel.removeEventListener("message", listen); resolve(false); },
                             CLAIM_WAIT_MS);
    function listen(event) {
      if (event.data && event.data.owns === id) {
        clearTimeout(timer);
        channel.removeEventListener("message", listen);
        resolve(true);
      }
    }
    channel.addEventListener("message", listen);
    channel.postMessage({ asks: id });
  });
}

export class Client {
  // grouping(): the grouping the page draws (its "group by").
  constructor(grouping) {
    this.grouping = grouping;
    this.session = null;
    this.held = null; // the last state received, as sent (its features a string)
    this.catalog = null;
    this.channel = "BroadcastChannel" in window ? new BroadcastChannel(CHANNEL) : null;
    if (this.channel) {
      this.channel.addEventListener("message", (event) => {
        if (event.data && event.data.asks && event.data.asks === this.session) {
          this.channel.postMessage({ owns: this.session });
        }
      });
    }
  }

  // The tab's state: its own session if the server still has it, else a new one.
  async start() {
    this.catalog = new Catalog((await request("GET", "/api/catalog")).features);
    const known = sessionStorage.getItem(KEY);
    if (known && !(this.channel && await claimedElsewhere(this.channel, known))) {
      try {
        return await this.whole(known);
      } catch (error) {
        if (!(error instanceof ApiError && error.status === 404)) throw error;
      }
    }
    return this.open();
  }

  async open() {
    return this.receive(await request("POST", "/api/session", { overview: this.grouping() }));
  }

  // The session's state whole, in overview mode under the page's grouping.
  async whole(session) {
    return this.receive(await request("POST", "/api/grouping", { session, grouping: this.grouping() }));
  }

  // {state, changes}: the state after an answer, its features read through the catalog, and
  // what it changed (null: everything, for a whole state; else {features: Set of ids}).
  async receive(answer) {
    const held = patch(this.held, answer);
    if (held === null) return this.whole(answer.session); // out of step: ask for all of it
    this.held = held;
    this.session = held.session;
    sessionStorage.setItem(KEY, held.session);
    const { features, changed } = this.catalog.read(held.features);
    const changes = "base" in answer && changed !== null ? { features: changed } : null;
    return { state: { ...held, features }, changes };
  }

  choose(action, feature, value) {
    const fields = { action, feature };
    if (value !== undefined) fields.value = value;
    return this.post("/api/choose", fields);
  }

  undo() { return this.post("/api/undo", {}); }
  redo() { return this.post("/api/redo", {}); }
  reset() { return this.post("/api/reset", {}); }
  finish() { return this.post("/api/finish", {}); }
  regroup() { return this.post("/api/grouping", { grouping: this.grouping() }); }

  // A page of a group's members in the session's current state (kind: nodes, params,
  // topics, services or actions).
  members(group, kind, page) {
    return request("POST", "/api/group", { session: this.session, group, kind, page });
  }

  // The links between groups (the closed boxes drawn) in the session's current state.
  links(groups) {
    return request("POST", "/api/links", { session: this.session, groups });
  }

  async post(path, fields) {
    const version = this.held?.version;
    return this.receive(await request("POST", path, { session: this.session, version, ...fields }));
  }
}
