"""A validator for the subset of JSON Schema that tests/assignments/results.schema.json uses
(type, properties, required, additionalProperties: false, enum, items, minimum, local $ref):
python3-jsonschema is not among the project's packages, and this subset is a page."""

TYPES = {"object": dict, "array": list, "string": str, "boolean": bool,
         "number": (int, float), "integer": int}
KNOWN = {"$schema", "$comment", "definitions", "type", "properties", "required",
         "additionalProperties", "enum", "items", "minimum", "$ref"}


def errors(value, schema, root=None, where="$"):
    """Every violation of `schema` by `value`, as 'path: what' strings (empty: valid)."""
    root = root if root is not None else schema
    unknown = set(schema) - KNOWN
    if unknown:
        return [f"{where}: the schema uses {sorted(unknown)}, which this validator does not know"]
    if "$ref" in schema:
        target = root
        for part in schema["$ref"].lstrip("#/").split("/"):
            target = target[part]
        return errors(value, target, root, where)
    out = []
    if "type" in schema:
        names = schema["type"] if isinstance(schema["type"], list) else [schema["type"]]
        ok = any(isinstance(value, TYPES[n]) and not (n in ("number", "integer") and isinstance(value, bool))
                 for n in names)
        if not ok:
            return [f"{where}: {type(value).__name__} is not {' or '.join(names)}"]
    if "enum" in schema and value not in schema["enum"]:
        out.append(f"{where}: {value!r} is not one of {schema['enum']}")
    if "minimum" in schema and isinstance(value, (int, float)) and value < schema["minimum"]:
        out.append(f"{where}: {value} is below {schema['minimum']}")
    if isinstance(value, dict):
        properties = schema.get("properties", {})
        out += [f"{where}: '{k}' is required" for k in schema.get("required", []) if k not in value]
        if schema.get("additionalProperties") is False:
            out += [f"{where}: '{k}' is not allowed" for k in value if k not in properties]
        for k, v in value.items():
            if k in properties:
                out += errors(v, properties[k], root, f"{where}.{k}")
    if isinstance(value, list) and "items" in schema:
        for i, v in enumerate(value):
            out += errors(v, schema["items"], root, f"{where}[{i}]")
    return out
