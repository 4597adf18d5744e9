#!/usr/bin/python3
"""Checks server/schema/ with an existing validator (Debian's python3-jsonschema). Run by ctest:

  check_schema.py --root REPO readme      the README's scene tables and the schema name the same fields
  check_schema.py --root REPO examples    every examples/*.json validates against the scene schema
  check_schema.py --root REPO generated --cases BINARY --count N --seed S
                                          N generated scenes: the schema accepts exactly those the parser
                                          accepts, except for the documented rules listed below
  check_schema.py --root REPO openapi --version V
                                          openapi.json validates against the OpenAPI 3.1 schema, its
                                          schemas are valid JSON Schemas, every route the server registers
                                          and every status of the README is in it

Each prints what it checked and ends with "N passed, N failed"; the exit code is 0 only when none failed.
"""
import argparse
import glob
import json
import os
import re
import subprocess
import sys

from jsonschema import Draft202012Validator

# Rules the parser enforces that a JSON Schema cannot state (relations between values, lengths of one array
# against another, what an upload or a model holds) and the service's limits. A generated scene that the
# schema accepts may be rejected by the parser only for one of these; each is also in the schema's $comment.
DOCUMENTED_RULES = [
    ("colors has one entry per point or position", lambda c: '"colors" needs one colour per' in c["message"]),
    ("normals has one entry per position", lambda c: '"normals" needs one normal per position' in c["message"]),
    ("mesh indices are below the number of positions",
     lambda c: re.search(r"index .* is outside the \d+ positions", c["message"])),
    ("a flat positions/normals/indices list holds triples",
     lambda c: "is not a multiple of 3" in c["message"]),
    ("camera near < far (given or fitted)",
     lambda c: re.search(r'"far" must be greater than "near"|"near" must be less than "far"', c["message"])),
    ("camera eye != target (given or fitted)",
     lambda c: re.search(r'"eye" and "target" (are the same point|coincide)', c["message"])),
    ("camera up not along the view direction", lambda c: '"up" is parallel to the view direction' in c["message"]),
    ("source / mtl_source names an uploaded part", lambda c: "no uploaded part named" in c["message"]),
    ("OBJ and MTL text is a usable model (422)", lambda c: c["verdict"] == "model"),
    ("a texture's data is base64 of a PNG or JPEG (400; 422 for an image that does not decode)",
     lambda c: "not base64" in c["message"] or ("/channels/" in c["pointer"] and c["verdict"] == "model")),
    ("a shader's program compiles (400 invalid-shader)", lambda c: c["verdict"] == "shader"),
    ("a shader's uniforms are declared by its program, with its type's values",
     lambda c: re.search(r'the program declares no uniform|uniform ".*" (is a|takes true or false)', c["message"])),
    ("a uniform holds at most 4096 values, nested arrays included",
     lambda c: "a uniform holds at most 4096 values" in c["message"]),
    ("the service's limits (422; nesting depth 400)",
     lambda c: c["verdict"] == "limit" or "nested deeper than" in c["message"]),
]

README_SECTIONS = ("## Scene format v1", "## Shaders", "## 3D scenes and models")


class Result:
    def __init__(self):
        self.passed = self.failed = 0

    def check(self, ok, what):
        if ok:
            self.passed += 1
        else:
            self.failed += 1
            print("FAIL " + what)
        return ok

    def finish(self, name):
        print(f"{name}: {self.passed} passed, {self.failed} failed")
        return 0 if self.failed == 0 and self.passed > 0 else 1


def load(path):
    with open(path, encoding="utf-8") as f:
        return json.load(f)


def walk(node, visit, path=""):
    visit(node, path)
    if isinstance(node, dict):
        for k, v in node.items():
            walk(v, visit, path + "/" + k)
    elif isinstance(node, list):
        for i, v in enumerate(node):
            walk(v, visit, path + "/" + str(i))


def schema_names(schema):
    """(property names, string values of enum/const) anywhere in the schema."""
    fields, values = set(), set()

    def visit(node, path):
        if not isinstance(node, dict):
            return
        if isinstance(node.get("properties"), dict):
            fields.update(node["properties"])
        for v in node.get("enum", []) if isinstance(node.get("enum"), list) else []:
            if isinstance(v, str):
                values.add(v)
        if isinstance(node.get("const"), str):
            values.add(node["const"])

    walk(schema, visit)
    return fields, values


def readme_table_rows(readme):
    """The rows of every `| field | meaning |` table in the README's scene sections."""
    rows, section, in_table = [], None, False
    for line in readme.splitlines():
        if line.startswith("## "):
            section = line if line.startswith(README_SECTIONS) else None
            in_table = False
        if section is None:
            continue
        if re.match(r"^\|\s*field\s*\|\s*meaning\s*\|\s*$", line):
            in_table = True
            continue
        if in_table and line.startswith("|---"):
            continue
        if in_table and line.startswith("|"):
            rows.append(line)
        else:
            in_table = False
    return rows


def check_readme(args):
    r = Result()
    schema = load(os.path.join(args.root, "server/schema/scene.schema.json"))
    with open(os.path.join(args.root, "README.md"), encoding="utf-8") as f:
        rows = readme_table_rows(f.read())
    r.check(len(rows) >= 15, f"found {len(rows)} rows in the README's field tables (expected both tables)")
    fields, values = schema_names(schema)
    named = set()
    for row in rows:
        # A name in quotes or backticks is a field, unless it is a value: after `"key": `, an enum or const
        # of the schema, or a JSON literal.
        for m in re.finditer(r'(?:"(\$?[A-Za-z_][A-Za-z0-9_]*)"|`(\$?[A-Za-z_][A-Za-z0-9_]*)`)', row):
            name = m.group(1) or m.group(2)
            if re.search(r'"\s*:\s*$', row[: m.start()]) or name in ("true", "false", "null"):
                continue
            if name in fields:
                named.add(name)
            elif name not in values:
                r.check(False, f"README names `{name}` (row: {row[:80]}...), which the schema has neither as a "
                               "field nor as a value")
    for name in sorted(fields):
        r.check(name in named, f"the schema's field `{name}` is in no README table")
    for name in sorted(named):
        r.check(True, name)
    print(f"fields in both: {', '.join(sorted(named))}")
    return r.finish("readme")


def check_examples(args):
    r = Result()
    validator = Draft202012Validator(load(os.path.join(args.root, "server/schema/scene.schema.json")))
    files = sorted(glob.glob(os.path.join(args.root, "examples/*.json")))
    r.check(len(files) >= 5, f"found {len(files)} examples")
    for path in files:
        errors = list(validator.iter_errors(load(path)))
        r.check(not errors, f"{os.path.basename(path)}: " + "; ".join(
            f"{'/'.join(map(str, e.absolute_path))}: {e.message}" for e in errors[:3]))
        if not errors:
            print(f"ok   {os.path.basename(path)}")
    return r.finish("examples")


def error_paths(errors):
    """JSON pointers of schema errors, with those inside anyOf/oneOf branches."""
    out = set()
    for e in errors:
        out.add("".join("/" + str(p) for p in e.absolute_path))
        out |= error_paths(e.context or [])
    return out


def related(a, b):
    return a == b or a.startswith(b + "/") or b.startswith(a + "/") or a == "" or b == ""


def check_generated(args):
    r = Result()
    schema = load(os.path.join(args.root, "server/schema/scene.schema.json"))
    Draft202012Validator.check_schema(schema)
    validator = Draft202012Validator(schema)
    out = subprocess.run([args.cases, str(args.count), str(args.seed)], check=True, capture_output=True, text=True)
    cases = [json.loads(line) for line in out.stdout.splitlines()]
    r.check(len(cases) == args.count, f"{len(cases)} cases generated, {args.count} asked for")
    counts = {"both accept": 0, "both reject": 0}
    rule_counts = {name: 0 for name, _ in DOCUMENTED_RULES}
    shown = 0
    for case in cases:
        doc = json.loads(case["doc"])
        errors = list(validator.iter_errors(doc))
        parser_ok = case["verdict"] == "accepted"
        if parser_ok and not errors:
            counts["both accept"] += 1
            r.passed += 1
        elif not parser_ok and errors:
            counts["both reject"] += 1
            # The schema should object where the parser did (the parser stops at its first error, so that
            # one must be among the schema's, unless it is a rule the schema cannot state).
            documented = any(rule(case) for _, rule in DOCUMENTED_RULES)
            if documented or any(related(case["pointer"], p) for p in error_paths(errors)):
                r.passed += 1
            else:
                r.check(False, f"both reject, but not at the same place: parser {case['pointer']!r} "
                               f"({case['message']}), schema at {sorted(error_paths(errors))}\n  {case['doc']}")
        elif parser_ok:
            shown += 1
            r.check(False, "the schema rejects a scene the parser accepts: " + "; ".join(
                f"{'/'.join(map(str, e.absolute_path))}: {e.message[:120]}" for e in errors[:2]) +
                f"\n  {case['doc']}")
        else:
            rules = [name for name, rule in DOCUMENTED_RULES if rule(case)]
            if rules:
                rule_counts[rules[0]] += 1
                r.passed += 1
            else:
                r.check(False, f"the schema accepts a scene the parser rejects ({case['verdict']} at "
                               f"{case['pointer']!r}: {case['message']}), for no documented rule\n  {case['doc']}")
    for name, n in counts.items():
        print(f"{name}: {n}")
    print("schema accepts, parser rejects by a documented rule:")
    for name, n in rule_counts.items():
        print(f"  {n:5d}  {name}")
    # Both verdicts must be well represented, or the comparison says little.
    r.check(counts["both accept"] >= args.count // 5, f"only {counts['both accept']} scenes accepted by both")
    r.check(counts["both reject"] >= args.count // 5, f"only {counts['both reject']} scenes rejected by both")
    return r.finish("generated")


def server_routes(root):
    """(method, path) of every route the server registers, read from server/*.cpp."""
    routes = set()
    for path in glob.glob(os.path.join(root, "server/*.cpp")):
        with open(path, encoding="utf-8") as f:
            text = f.read()
        for m in re.finditer(r'\.\s*(Get|Post|Put|Delete|Patch|Options)\(\s*(?:R"\((.*?)\)"|"([^"]*)")', text):
            route = re.sub(r"\([^)]*\)", "{}", m.group(2) or m.group(3))  # a regex group: a path parameter
            routes.add((m.group(1).lower(), route))
        # server/routes.cpp's table: {"pattern", "METHODS", "path", add}; HEAD is answered by GET's handler.
        for m in re.finditer(r'\{"(/[^"]*)",\s*"([A-Z, ]+)",', text):
            route = re.sub(r"\{[^}]*\}", "{}", m.group(1))
            routes.update((method.lower(), route) for method in m.group(2).split(", ") if method != "HEAD")
    return routes


def check_openapi(args):
    r = Result()
    doc = load(os.path.join(args.root, "server/schema/openapi.json"))
    # The OpenAPI 3.1 schema is third-party text, not kept in the repository: `make test-openapi` fetches it
    # from the npm registry (scripts/test-openapi) and passes it here. Without it (make test) the checks
    # below still run: references, Schema Objects, routes and statuses.
    if args.oas_schema:
        meta = load(args.oas_schema)
        errors = list(Draft202012Validator(meta).iter_errors(doc))
        r.check(not errors, "openapi.json against the OpenAPI 3.1 schema: " + "; ".join(
            f"{'/'.join(map(str, e.absolute_path))}: {e.message[:160]}" for e in errors[:5]))
    r.check(doc.get("info", {}).get("version") == args.version,
            f"info.version {doc.get('info', {}).get('version')!r} is not the project's {args.version!r}")

    # Every Schema Object is a valid JSON Schema 2020-12 (the OpenAPI schema checks only their shape).
    def visit(node, path):
        if isinstance(node, dict) and isinstance(node.get("schema"), dict):
            try:
                Draft202012Validator.check_schema(node["schema"])
                r.passed += 1
            except Exception as e:  # jsonschema.SchemaError
                r.check(False, f"{path}/schema: {e}")
        # Every internal reference resolves; the one external one is the scene schema where it is served.
        if isinstance(node, dict) and isinstance(node.get("$ref"), str):
            ref = node["$ref"]
            if ref.startswith("#/"):
                target = doc
                for part in ref[2:].split("/"):
                    target = target.get(part) if isinstance(target, dict) else None
                r.check(target is not None, f"{path}: $ref {ref} does not resolve")
            else:
                r.check(ref == "/schema/scene.json", f"{path}: unexpected external $ref {ref}")

    walk(doc, visit)
    for name, s in doc.get("components", {}).get("schemas", {}).items():
        Draft202012Validator.check_schema(s)

    # Every route the server registers is described.
    documented = {(method, re.sub(r"\{[^}]*\}", "{}", path))
                  for path, item in doc.get("paths", {}).items() for method in item
                  if method in ("get", "post", "put", "delete", "patch", "options", "head")}
    routes = server_routes(args.root)
    r.check(len(routes) >= 6, f"found only {len(routes)} routes in server/*.cpp")
    for method, path in sorted(routes):
        r.check((method, path) in documented, f"{method.upper()} {path} is served but not in openapi.json")
    for method, path in sorted(documented - routes):
        r.check(False, f"{method.upper()} {path} is in openapi.json but not served")
    print("routes: " + ", ".join(f"{m.upper()} {p}" for m, p in sorted(routes)))

    # Every status of the README's status table is answered somewhere in the document.
    with open(os.path.join(args.root, "README.md"), encoding="utf-8") as f:
        readme = f.read()
    table = re.search(r"^\| status \| when \|\n((?:\|.*\n)+)", readme, re.M)
    statuses = set()
    if r.check(table is not None, "the README's `| status | when |` table"):
        for row in table.group(1).splitlines()[1:]:
            statuses |= set(re.findall(r"\b([1-5]\d\d)\b", row.split("|")[1]))
    answered = {code for item in doc.get("paths", {}).values() for op in item.values()
                if isinstance(op, dict) for code in op.get("responses", {})}
    for status in sorted(statuses):
        r.check(status in answered, f"status {status} of the README is in no response of openapi.json")
    print("statuses: " + ", ".join(sorted(statuses)))
    return r.finish("openapi")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--root", required=True, help="the repository")
    sub = parser.add_subparsers(dest="what", required=True)
    sub.add_parser("readme")
    sub.add_parser("examples")
    g = sub.add_parser("generated")
    g.add_argument("--cases", required=True, help="the schema_cases binary")
    g.add_argument("--count", type=int, default=3000)
    g.add_argument("--seed", type=int, default=16)
    o = sub.add_parser("openapi")
    o.add_argument("--version", required=True, help="the CMake project version")
    o.add_argument("--oas-schema", help="the OpenAPI 3.1 schema (JSON) to validate against")
    args = parser.parse_args()
    return {"readme": check_readme, "examples": check_examples, "generated": check_generated,
            "openapi": check_openapi}[args.what](args)


if __name__ == "__main__":
    sys.exit(main())
