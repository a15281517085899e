// Applying the server's answers to the state the page holds (the server's side and the
// format: src/rosvar/outputs/web/delta.py, whose patch() this mirrors).
//
// An answer with a "base" is a delta against the state of that version: "features" holds
// the changed features only, "graph" per changed list {removed: [ids], added: [[index,
// entry]], changed: [[index, fields]]} (drop, insert in order of place, merge), and any other
// field is present only when its value changed. An answer without "base" is the whole state.

export const KEYED = "features";
export const LISTS = "graph";

// The new state, or null when the delta was made against another version than state's.
export function patch(state, answer) {
  if (!("base" in answer)) return answer;
  if (!state || answer.base !== state.version) return null;
  const result = { ...state };
  for (const [key, value] of Object.entries(answer)) {
    if (key === KEYED) result[key] = { ...state[key], ...value };
    else if (key === LISTS) {
      result[key] = { ...state[key] };
      for (const [kind, change] of Object.entries(value)) {
        result[key][kind] = patchList(state[key][kind] ?? [], change);
      }
    } else if (key !== "base") result[key] = value;
  }
  return result;
}

function patchList(entries, change) {
  const gone = new Set(change.removed);
  const result = entries.filter((entry) => !gone.has(entry.id));
  for (const [index, entry] of change.added) result.splice(index, 0, entry); // in order of place
  for (const [index, fields] of change.changed) result[index] = { ...result[index], ...fields };
  return result;
}

// What an answer changed, for views that update only that: null (everything) for a whole
// state, else {features: Set of ids, graph: Set of entry ids, fields: Set of other fields};
// state is the state after the answer (changed entries are known by their place in it).
export function touched(answer, state) {
  if (!("base" in answer)) return null;
  const graph = new Set();
  for (const [kind, change] of Object.entries(answer[LISTS] ?? {})) {
    for (const id of change.removed) graph.add(id);
    for (const [, entry] of change.added) graph.add(entry.id);
    for (const [index] of change.changed) graph.add(state[LISTS][kind][index].id);
  }
  return {
    features: new Set(Object.keys(answer[KEYED] ?? {})),
    graph,
    fields: new Set(Object.keys(answer).filter((key) => key !== KEYED && key !== LISTS)),
  };
}
