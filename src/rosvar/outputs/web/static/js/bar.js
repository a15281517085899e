// The bar: counts, undo/redo/reset/finish, messages, the notice of a refused choice, and the
// command with its copy button.

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
    e.command.classList.toggle("pending", !command);
    e.command.textContent = command ? state.command : pendingText(state);
    e.copy.disabled = !command;
    e.copy.textContent = "Copy";
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
