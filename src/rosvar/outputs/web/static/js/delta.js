// Applying the server's answers to the state the page holds (the server's side and the
// format: src/rosvar/outputs/web/delta.py, whose patch() this mirrors for the states of
// overview mode, the page's).
//
// An answer with a "base" is a delta against the state of that version: "graph" holds per
// changed list {removed: [ids], added: [[index, entry]], changed: [[index, fields]]} (drop,
// insert in order of place, merge), "conflicts" {removed: [places], added: [[index, entry]]}
// (drop the entries at those places of the old list, insert), and any other field (the
// features' string too) is present only when its value changed. An answer without "base"
// is the whole state.

export const LISTS = "graph";
const SEQUENCES = new Set(["conflicts"]);

// The new state, or null when the delta was made against another version than state's.
export function patch(state, answer) {
  if (!("base" in answer)) return answer;
  if (!state || answer.base !== state.version) return null;
  const result = { ...state };
  for (const [key, value] of Object.entries(answer)) {
    if (key === LISTS) {
      result[key] = { ...state[key] };
      for (const [kind, change] of Object.entries(value)) {
        result[key][kind] = patchList(state[key][kind] ?? [], change);
      }
    } else if (SEQUENCES.has(key) && !Array.isArray(value)) {
      result[key] = patchSequence(state[key] ?? [], value);
    } else if (key !== "base") result[key] = value;
  }
  return result;
}

function patchSequence(entries, change) {
  const gone = new Set(change.removed);
  const result = entries.filter((_entry, place) => !gone.has(place));
  for (const [index, entry] of change.added) result.splice(index, 0, entry); // in order of place
  return result;
}

function patchList(entries, change) {
  const gone = new Set(change.removed);
  const result = entries.filter((entry) => !gone.has(entry.id));
  for (const [index, entry] of change.added) result.splice(index, 0, entry); // in order of place
  for (const [index, fields] of change.changed) result[index] = { ...result[index], ...fields };
  return result;
}
