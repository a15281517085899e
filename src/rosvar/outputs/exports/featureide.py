"""The feature model as FeatureIDE XML (``model.xml``), readable by FeatureIDE and flamapy.

Names are rosvar's feature ids: XML escapes any character, so only control characters
(not allowed in XML 1.0) and ``%`` are percent-encoded. ``conj``/``disj`` are written as
binary trees because flamapy's reader takes just the first two children of each; a
constraint's reason goes in a comment, which both readers skip (a ``description``
element would be taken for a formula by flamapy).
"""

from __future__ import annotations

from xml.etree import ElementTree as ET

from rosvar.analyses.feature_model.features import ArgFeature, FileFeature
from rosvar.analyses.feature_model.model import FeatureModel
from rosvar.outputs.exports._common import Entry, Tree
from rosvar.outputs.exports._formula import And, Formula, Implies, Not, Or, Var, exported


def _rule(parent: ET.Element, f: Formula, names: dict[str, str]) -> None:
    """Append ``f`` under ``parent`` in FeatureIDE's rule syntax (binary conj/disj)."""
    if isinstance(f, Var):
        ET.SubElement(parent, "var").text = names[f.name]
    elif isinstance(f, Not):
        _rule(ET.SubElement(parent, "not"), f.operand, names)
    elif isinstance(f, Implies):
        implication = ET.SubElement(parent, "imp")
        _rule(implication, f.premise, names)
        _rule(implication, f.conclusion, names)
    else:
        operands = f.operands
        if len(operands) == 1:
            _rule(parent, operands[0], names)
            return
        element = ET.SubElement(parent, "conj" if isinstance(f, And) else "disj")
        _rule(element, operands[0], names)
        rest = And(operands[1:]) if isinstance(f, And) else Or(operands[1:])
        _rule(element, rest, names)


def _feature(parent: ET.Element, entry: Entry, children: list[Entry], name: str) -> ET.Element:
    feature = entry.feature
    attributes: dict[str, str] = {}
    if isinstance(feature, ArgFeature):
        tag = "alt" if children else "feature"
        attributes["abstract"] = "true"
        attributes["mandatory"] = "true"  # flamapy takes the attribute's presence as "mandatory"
    elif isinstance(feature, FileFeature):
        tag = "and" if children else "feature"
    else:
        tag = "feature"
    attributes["name"] = name
    return ET.SubElement(parent, tag, attributes)


def write(model: FeatureModel) -> str:
    """``<featureModel>``: root ``and`` → optional files → mandatory ``alt`` args → values."""
    tree = Tree(model)
    names = tree.names()
    document = ET.Element("featureModel")
    document.append(
        ET.Comment(
            f" rosvar feature model of {tree.root}: launch files (optional) > args"
            " (mandatory, abstract) > values (alternative) "
        )
    )
    struct = ET.SubElement(document, "struct")
    root = ET.SubElement(
        struct, "and", {"abstract": "true", "mandatory": "true", "name": names[tree.root]}
    )
    elements: dict[str, ET.Element] = {}
    for entry in tree.entries:
        parent = root if entry.parent is None else elements[entry.parent]
        children = tree.children.get(entry.id, [])
        elements[entry.id] = _feature(parent, entry, children, names[entry.id])
    constraints = ET.SubElement(document, "constraints")  # flamapy needs it even when empty
    for constraint in exported(tree):
        constraints.append(ET.Comment(" " + _comment(constraint.text) + " "))
        _rule(ET.SubElement(constraints, "rule"), constraint.formula, names)
    ET.indent(document, space="\t")
    body = ET.tostring(document, encoding="unicode")
    return '<?xml version="1.0" encoding="UTF-8" standalone="no"?>\n' + body + "\n"


def _comment(text: str) -> str:
    """Comment text: one line, and never ``--`` (XML forbids it inside comments)."""
    flat = " ".join(text.split())
    while "--" in flat:
        flat = flat.replace("--", "- -")
    return flat.rstrip("-")
