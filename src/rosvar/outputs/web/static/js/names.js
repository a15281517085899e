// Short, readable names for the long paths and ids the server sends.

// The file feature a graph entry belongs to: the engine's graph ids start with it
// ("FILE|basename:line:col#n", src/rosvar/configuration/graph.py).
export function entryFile(id) {
  const cut = String(id).indexOf("|");
  return cut > 0 ? String(id).slice(0, cut) : "";
}

// The ROS package of a launch file path: the directory above launch/, else the parent one.
export function packageOfPath(path) {
  const parts = String(path).split("/");
  const launch = parts.lastIndexOf("launch");
  if (launch > 0) return parts[launch - 1];
  return parts.length > 1 ? parts[parts.length - 2] : ".";
}

// The ROS package of a file feature: the engine's field, else from its path.
export function packageOf(feature) {
  return feature.package ?? packageOfPath(feature.file);
}

// "pkg/sub/file.launch" for a launch file's path or id, as people name it.
export function shortPath(path) {
  const text = String(path);
  const parts = text.split("/");
  const launch = parts.lastIndexOf("launch");
  if (launch > 0) return [parts[launch - 1], ...parts.slice(launch + 1)].join("/");
  return parts.slice(-2).join("/");
}

// Every launch-file path in a text (engine messages name files by long relative paths).
export function shortenPaths(text) {
  return String(text).replace(/(?:[\w.⟨⟩-]+\/)+[\w.⟨⟩-]+\.(?:launch|xml|test|py|yaml|yml)\b/g, shortPath);
}

export function baseName(path) {
  const text = String(path);
  return text.slice(text.lastIndexOf("/") + 1);
}

// 87925366…0 → "≈ 8.8 × 10⁷⁶": counts too long to read are rounded (the exact one on hover).
const SUPERSCRIPT = "⁰¹²³⁴⁵⁶⁷⁸⁹";
export const EXACT_DIGITS = 9;

export function readableCount(value) {
  const digits = String(value).replace(/^-/, "");
  if (digits.length <= EXACT_DIGITS) return Number(value).toLocaleString("en");
  const exponent = digits.length - 1;
  const rounded = Math.round(Number(`${digits[0]}.${digits.slice(1, 3)}`) * 10) / 10;
  const [mantissa, power] = rounded >= 10 ? ["1.0", exponent + 1] : [rounded.toFixed(1), exponent];
  const sup = String(power).split("").map((d) => SUPERSCRIPT[Number(d)]).join("");
  return `≈ ${mantissa} × 10${sup}`;
}

// The exact count with thousands separators (counts above 2**53 come as decimal strings).
export function exactCount(value) {
  return String(value).replace(/\B(?=(\d{3})+(?!\d))/g, ",");
}
