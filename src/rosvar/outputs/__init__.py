"""What rosvar shows: the command line, the JSON documents of its results, the feature-model
exports and the web UI.

The layers below keep values and conditions; presentation (tables, JSON, SARIF, UVL, the
page) is decided here only, so a new output never changes an analysis.
"""
