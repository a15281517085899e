// The bar: counts, undo/redo/reset/finish, messages, and the command with its copy button.

function formatCount(value) {
  // the server sends counts above 2**53 as decimal strings
  return typeof value === "number" ? value.toLocaleString("en") : String(value);
}

export class Bar {
  constructor(elements, handlers) {
    this.elements = elements;
    elements.undo.addEventListener("click", handlers.undo);
    elements.redo.addEventListener("click", handlers.redo);
    elements.reset.addEventListener("click", handlers.reset);
    elements.finish.addEventListener("click", handlers.finish);
    elements.copy.addEventListener("click", () => this.copy());
  }

  update(state) {
    const e = this.elements;
    e.featuresLeft.textContent = formatCount(state.unselected);
    e.configurations.textContent = formatCount(state.configurations);
    e.completeness.textContent = state.complete ? "complete" : "incomplete";
    e.completeness.classList.toggle("complete", state.complete);
    e.undo.disabled = !state.can_undo;
    e.redo.disabled = !state.can_redo;
    e.finish.disabled = state.complete;
    const command = state.complete && state.command !== null;
    e.command.classList.toggle("pending", !command);
    e.command.textContent = command ? state.command
      : `Choose features until none is left (${formatCount(state.unselected)} to go); the roslaunch command appears here.`;
    e.copy.disabled = !command;
    e.copy.textContent = "Copy";
    const refused = state.refused ?? [];
    const stops = (state.graph.errors ?? []).filter((error) => error.presence === "present");
    if (refused.length) {
      const last = refused[refused.length - 1];
      this.say(`Refused ${last.choice.action} ${last.choice.feature}: ${last.reason}`, true);
    } else if (stops.length) {
      const first = stops[0];
      this.say(`roslaunch would stop: ${first.message} (${first.file}:${first.line})`, true);
    }
  }

  say(text, refused = false) {
    this.elements.message.textContent = text;
    this.elements.message.classList.toggle("refused", refused);
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
