// The feature tree's fixed part (GET /api/catalog, once) and each state's selections, one
// character per feature in the catalog's order: together the features as the tree and the
// bar read them ({kind, file, package, arg, value, parent, doc?, state, derived} by id).

const SELECTIONS = {
  u: ["unselected", false],
  s: ["selected", false],
  d: ["deselected", false],
  S: ["selected", true],
  D: ["deselected", true],
};

export class Catalog {
  // rows: [id, kind, file, arg, value, parent row, default, package, doc] in tree order.
  constructor(rows) {
    this.ids = rows.map(([id]) => id);
    const fileRow = (row) => (rows[row][5] < 0 ? row : fileRow(rows[row][5]));
    this.fixed = rows.map(([, kind, , arg, value, parent, , , doc], row) => {
      const [, , file, , , , , pkg] = rows[fileRow(row)];
      const fixed = { kind, file, package: pkg, arg, value, parent: parent < 0 ? null : rows[parent][0] };
      if (doc) fixed.doc = doc;
      return fixed;
    });
    // arg id → the id of its default value
    this.defaults = Object.fromEntries(rows.filter((row) => row[6]).map(([id, , , , , parent]) => [rows[parent][0], id]));
    this.selection = null;
    this.features = null;
  }

  // {features, changed}: the features under `selection`, and the ids whose state changed
  // since the last call (null: all of them, on the first).
  read(selection) {
    const first = this.selection === null;
    const changed = new Set();
    if (selection !== this.selection) {
      const features = {};
      this.ids.forEach((id, row) => {
        const code = selection[row];
        if (!first && code === this.selection[row]) { features[id] = this.features[id]; return; }
        const [state, derived] = SELECTIONS[code];
        features[id] = { ...this.fixed[row], state, derived };
        changed.add(id);
      });
      this.selection = selection;
      this.features = features;
    }
    return { features: this.features, changed: first ? null : changed };
  }
}
