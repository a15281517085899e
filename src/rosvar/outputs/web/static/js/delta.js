// Applying the server's answers to the state the page holds (the server's side and the
// format: src/rosvar/outputs/web/delta.py, whose patch() this mirrors).
//
// An answer with a "base" is a delta against the state of that version: "features" holds
// the changed features only, "graph" per changed list {removed: [ids], put: [[index, entry]]}
// (an entry with the id of the entry at that place holds only its changed fields), and any
// other field is present only when its value changed. An answer without "base" is the whole
// state.

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
  // in order of place: the entries before `index` are already the new list's
  for (const [index, entry] of change.put) {
    if (index < result.length && result[index].id === entry.id) result[index] = { ...result[index], ...entry };
    else result.splice(index, 0, entry);
  }
  return result;
}

// What an answer changes, for views that update only that: null (everything) for a whole
// state, else {features: Set of ids, graph: Set of entry ids, fields: Set of other fields}.
export function touched(answer) {
  if (!("base" in answer)) return null;
  const graph = new Set();
  for (const change of Object.values(answer[LISTS] ?? {})) {
    for (const id of change.removed) graph.add(id);
    for (const [, entry] of change.put) graph.add(entry.id);
  }
  return {
    features: new Set(Object.keys(answer[KEYED] ?? {})),
    graph,
    fields: new Set(Object.keys(answer).filter((key) => key !== KEYED && key !== LISTS)),
  };
}
