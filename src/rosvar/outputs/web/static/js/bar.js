// The bar: counts, undo/redo/reset/finish, messages, the notice of a refused choice, and the
// command with its copy button and, for as long as it lasts, what stops the product from
// launching or from being known (a line under the command that no click clears).

import { exactCount, readableCount, shortPath, shortenPaths } from "./names.js";

// "select um7.launch", "set model of robot.launch to "husky"", ... as people say it.
function describe(choice, features) {
  const feature = features[choice.feature];
  const file = feature ? shortPath(feature.file) : shortenPaths(choice.feature);
  if (choice.action === "set") return `set ${feature?.arg ?? choice.feature} of ${file} to "${choice.value}"`;
  const verb = choice.action === "unselect" ? "take back your choice of" : choice.action;
  if (!feature || feature.kind === "file") return `${verb} ${file}`;
  if (feature.kind === "arg") return `${verb} the arg ${feature.arg} of ${file}`;
  return `${verb} ${feature.arg} = ${feature.value} in ${file}`;
}

// The engine's reason ("X is impossible after Y, Z: because; because") as sentences.
export function refusalText(refusal, features) {
  const match = / is impossible(?: after (.*?))?: (.*)$/s.exec(refusal.reason);
  const head = `Not applied: ${describe(refusal.choice, features)}.`;
  if (!match) return [head, shortenPaths(refusal.reason)];
  const [, after, because] = match;
  const lines = [head];
  if (after) lines.push(`It cannot go with your earlier choice${after.includes(", ") ? "s" : ""}: ${shortenPaths(after)}.`);
  lines.push(`Why: ${shortenPaths(because)}.`);
  return lines;
}

export class Bar {
  constructor(elements, handlers) {
    this.elements = elements;
    elements.undo.addEventListener("click", handlers.undo);
    elements.redo.addEventListener("click", handlers.redo);
    elements.reset.addEventListener("click", handlers.reset);
    elements.finish.addEventListener("click", handlers.finish);
    elements.copy.addEventListener("click", () => this.copy());
    elements.noticeClose.addEventListener("click", () => this.dismiss());
  }

  update(state) {
    const e = this.elements;
    e.featuresLeft.textContent = readableCount(state.unselected);
    e.configurations.textContent = readableCount(state.configurations);
    e.configurations.title = `exactly ${exactCount(state.configurations)} valid configurations`;
    e.completeness.textContent = state.complete ? "complete" : "incomplete";
    e.completeness.classList.toggle("complete", state.complete);
    e.undo.disabled = !state.can_undo;
    e.redo.disabled = !state.can_redo;
    e.finish.disabled = state.complete;
    const command = state.complete && state.command !== null;
    const fails = command && state.launches === false;
    e.command.classList.toggle("pending", !command);
    e.command.classList.toggle("fails", fails);
    e.command.textContent = command ? state.command : pendingText(state);
    e.copy.disabled = !command || fails;
    e.copy.textContent = "Copy";
    const status = statusText(state, fails);
    e.status.hidden = status === null;
    e.status.textContent = status ?? "";
    e.status.classList.toggle("fails", fails);
    const refused = state.refused ?? [];
    const stops = (state.graph.errors ?? []).filter((error) => error.presence === "present");
    if (refused.length) {
      this.notify(refusalText(refused[refused.length - 1], state.features));
    }
    const stopKey = stops.map((error) => error.id).join(" ");
    if (!refused.length && stops.length && stopKey !== this.stopKey) { // told once, not every step
      const first = stops[0];
      this.notify([`the launch would stop on this configuration: ${first.message}`,
                   `at ${shortPath(first.file)}:${first.line}`
                   + (stops.length > 1 ? ` (and ${stops.length - 1} more such error${stops.length > 2 ? "s" : ""})` : "")]);
    }
    this.stopKey = stopKey;
  }

  say(text, refused = false) {
    this.elements.message.textContent = text;
    this.elements.message.classList.toggle("refused", refused);
  }

  // A notice over the page (it pushes nothing down), bounded and closed with its ×.
  notify(lines) {
    const paragraphs = lines.map((line) => {
      const p = document.createElement("p");
      p.textContent = line;
      return p;
    });
    this.elements.noticeText.replaceChildren(...paragraphs);
    this.elements.notice.hidden = false;
  }

  dismiss() {
    this.elements.notice.hidden = true;
  }

  async copy() {
    const text = this.elements.command.textContent;
    try {
      await navigator.clipboard.writeText(text);
    } catch {
      // no clipboard permission (e.g. headless): copy through a selection instead
      const range = document.createRange();
      range.selectNodeContents(this.elements.command);
      const selection = window.getSelection();
      selection.removeAllRanges();
      selection.addRange(range);
      document.execCommand("copy");
    }
    this.elements.copy.textContent = "Copied ✓";
  }
}

// Why the finished product does not launch (the first error its launch tool stops at, or the
// first certain clash), and what rosvar could not read of the selected files: null when neither.
function statusText(state, fails) {
  const lines = [];
  if (fails) {
    const tool = state.command.startsWith("ros2 launch ") ? "ros2 launch" : "roslaunch";
    const stops = (state.graph.errors ?? []).filter((error) => error.presence === "present");
    const clashes = (state.conflicts ?? []).filter((conflict) => conflict.status === "certain");
    const first = stops.length
      ? `${tool} would stop at ${shortPath(stops[0].file)}:${stops[0].line}: ${stops[0].message}`
      : `${tool} refuses ${clashes[0].names.slice(0, 3).join(", ")} twice (${clashes[0].files.map(shortPath).join(" and ")})`;
    const more = stops.length + clashes.length - 1;
    lines.push(`This product does not launch: ${first}${more > 0 ? ` (and ${more} more)` : ""}.`);
  }
  const unknown = state.unknown ?? [];
  if (unknown.length) {
    const [first] = unknown;
    const more = unknown.length > 1 ? ` (and ${unknown.length - 1} more place${unknown.length > 2 ? "s" : ""})` : "";
    lines.push(`rosvar could not read all of the selected files: ${shortPath(first.file)}:${first.line}: ${first.message}${more}. What is shown may lack what they load.`);
  }
  return lines.length ? lines.join(" ") : null;
}

// What the command still waits for: open features, the text of an <other> value (a complete
// product can lack one), or a file to launch.
function pendingText(state) {
  if (!state.complete) {
    return `Choose features until none is left (${readableCount(state.unselected)} to go); the launch command appears here.`;
  }
  const untyped = state.untyped ?? [];
  if (!untyped.length) return "Nothing to launch: no launch file is selected.";
  const named = untyped.slice(0, 3).map((id) => {
    const arg = state.features[id];
    return arg ? `${arg.arg} of ${shortPath(arg.file)}` : shortenPaths(id);
  });
  const more = untyped.length > 3 ? ` and ${untyped.length - 3} more` : "";
  return `Type a value of your own for ${named.join(", ")}${more}; the launch command appears then.`;
}
