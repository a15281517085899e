"""The JSON documents of rosvar's results, shared by the commands (``--json``) and the web UI.

The domain's objects keep values and conditions; these modules say how they are written
(``docs/json-schema.md`` and ``docs/schema/``), one module per kind of result."""
