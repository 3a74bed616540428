#!/usr/bin/env python3
"""Generates include/GL/glext.h from the Khronos OpenGL registry gl.xml.

    python3 tools/gen_glext.py            # writes include/GL/glext.h
    python3 tools/gen_glext.py --check    # exits 1 when the committed file is stale

The registry is Debian's `khronos-api` package (/usr/share/khronos-api/gl.xml, installed by
scripts/ensure-deps.sh); `--registry PATH` reads another copy.

The header has the layout of Mesa's glext.h (the one of Debian's libgl-dev that Mesa
22.3.6 programs compile against): one `#ifndef NAME` block per OpenGL version 1.2-4.6
(compatibility profile) and per extension the registry marks as supported by desktop GL,
versions first, then ARB, KHR and OES extensions, then the other vendors, each group in
name order. Each block defines its feature macro, the types, tokens and `PFNGL...PROC`
function-pointer types it introduces, and its prototypes behind `GL_GLEXT_PROTOTYPES`.
Like the registry's own header generator, every type, token and function is declared once,
in the first block that requires it; what GL 1.0/1.1 require belongs to gl.h.

Nothing here says which functions softgl exports: as with Mesa, a program that calls a
declared function the library does not export fails to link. tests/headers.rs checks that
every function softgl exports is declared here with the C signature of its Rust definition.
"""
import argparse
import os
import sys
import xml.etree.ElementTree as ET

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
REGISTRY = "/usr/share/khronos-api/gl.xml"
OUTPUT = os.path.join(ROOT, "include", "GL", "glext.h")

# The GL_GLEXT_VERSION of Mesa's glext.h, whose set of blocks this header reproduces.
GLEXT_VERSION = "20220530"

# Blocks of Mesa's glext.h that the registry no longer lists (they declare only their
# feature macro).
EXTRA_EMPTY = ["GL_EXT_shader_samples_identical"]

# Versions whose declarations gl.h owns: their types, tokens and functions are not repeated.
GL_H_VERSIONS = ("GL_VERSION_1_0", "GL_VERSION_1_1")

# The registry spells fixed-size types with KHR/khrplatform.h's names; the header spells
# them as khrplatform.h defines them on Unix, so it needs only <stdint.h>.
KHRONOS_TYPES = {
    "khronos_int8_t": "signed char",
    "khronos_uint8_t": "unsigned char",
    "khronos_int16_t": "signed short int",
    "khronos_uint16_t": "unsigned short int",
    "khronos_int32_t": "int32_t",
    "khronos_uint32_t": "uint32_t",
    "khronos_int64_t": "int64_t",
    "khronos_uint64_t": "uint64_t",
    "khronos_intptr_t": "signed long int",
    "khronos_ssize_t": "signed long int",
    "khronos_float_t": "float",
}

PREAMBLE = """\
/*
 * GL/glext.h - OpenGL 1.2-4.6 and extensions: tokens, types, function-pointer types and
 * (with GL_GLEXT_PROTOTYPES) prototypes
 *
 * softgl: a software OpenGL 1.5 implementation with Mesa's OSMesa API. Only some of the
 * functions declared here are exported by libsoftgl; look the others up with
 * OSMesaGetProcAddress, which returns NULL for what softgl does not implement.
 *
 * GENERATED FILE, DO NOT EDIT. Produced from the Khronos registry gl.xml with
 *   python3 tools/gen_glext.py
 * (tests/headers.rs fails when this file is stale).
 */

#ifndef __gl_glext_h_
#define __gl_glext_h_ 1
/* The include guard of older Mesa glext.h versions. */
#define __glext_h_ 1

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#ifndef APIENTRY
#define APIENTRY
#endif
#ifndef APIENTRYP
#define APIENTRYP APIENTRY *
#endif
#ifndef GLAPI
#define GLAPI extern
#endif

#define GL_GLEXT_VERSION {version}
"""

EPILOGUE = """\
#ifdef __cplusplus
}
#endif

#endif /* __gl_glext_h_ */
"""


def text_of(elem, apientry="APIENTRY"):
    """The C text of a registry element: its text with <apientry/> spelled out."""
    parts = [elem.text or ""]
    for child in elem:
        parts.append(apientry if child.tag == "apientry" else text_of(child, apientry))
        parts.append(child.tail or "")
    return "".join(parts)


def c_type(text):
    """Registry type text with the khrplatform.h names replaced."""
    for k, v in KHRONOS_TYPES.items():
        text = text.replace(k, v)
    return text


def for_gl(elem):
    """True unless the element is restricted to another API or to the core profile."""
    return elem.get("api") in (None, "gl") and elem.get("profile") in (None, "compatibility")


class Registry:
    """The parts of gl.xml the header needs, indexed by name."""

    def __init__(self, path):
        root = ET.parse(path).getroot()
        self.types = {}
        for t in root.find("types"):
            if t.tag != "type" or t.get("api") not in (None, "gl"):
                continue
            name = t.get("name") or t.find("name").text
            self.types[name] = t
        self.enums = {}
        for group in root.findall("enums"):
            for e in group.findall("enum"):
                if e.get("api") in (None, "gl"):
                    self.enums.setdefault(e.get("name"), e)
        self.commands = {}
        for c in root.find("commands"):
            self.commands[c.find("proto").find("name").text] = c
        self.features = [f for f in root.findall("feature") if f.get("api") == "gl"]
        self.extensions = [
            e
            for e in root.find("extensions")
            if "gl" in (e.get("supported") or "").split("|")
        ]


def command_parts(cmd):
    """(return type, name, parameter list) of a registry command."""
    proto = cmd.find("proto")
    name = proto.find("name").text
    ret = text_of(proto).strip()
    ret = ret[: len(ret) - len(name)].strip()
    params = [" ".join(text_of(p).split()) for p in cmd.findall("param")]
    return c_type(ret), name, ", ".join(params) or "void"


def ret_prefix(ret):
    """`RET ` or `RET*` (no space after a pointer)."""
    return ret if ret.endswith("*") else ret + " "


class Emitter:
    """Declares each type, token and function once, in the first block requiring it."""

    def __init__(self, reg):
        self.reg = reg
        self.declared = set()

    def required(self, feature):
        """The (kind, name) items a feature or extension requires for GL compatibility."""
        out = []
        for req in feature.findall("require"):
            if for_gl(req):
                out.extend((item.tag, item.get("name")) for item in req)
        return out

    def type_lines(self, name, lines):
        """Appends the typedef of `name`, after the types it depends on, unless declared."""
        if name in self.declared or name not in self.reg.types:
            return
        self.declared.add(name)
        t = self.reg.types[name]
        dep = t.get("requires")
        if dep and dep != "khrplatform":
            self.type_lines(dep, lines)
        if name != "khrplatform":
            lines.append(c_type(text_of(t)))

    def command_types(self, cmd):
        """Names of the types a command's return value and parameters use."""
        return [p.text for p in cmd.iter("ptype")]

    def mark(self, feature):
        """Records a gl.h feature's declarations as made."""
        for kind, name in self.required(feature):
            self.declared.add(name)
            if kind == "command" and name in self.reg.commands:
                self.declared.update(self.command_types(self.reg.commands[name]))

    def block(self, name, feature):
        """The `#ifndef NAME` block of one version or extension."""
        types, tokens, pfns, protos = [], [], [], []
        for kind, item in self.required(feature) if feature is not None else []:
            if kind == "type":
                self.type_lines(item, types)
            elif kind == "enum" and item not in self.declared:
                self.declared.add(item)
                e = self.reg.enums[item]
                tokens.append(f"#define {item:<40} {e.get('value')}{e.get('type') or ''}")
            elif kind == "command" and item not in self.declared:
                self.declared.add(item)
                cmd = self.reg.commands[item]
                for t in self.command_types(cmd):
                    self.type_lines(t, types)
                ret, fname, params = command_parts(cmd)
                pfns.append(
                    f"typedef {ret_prefix(ret)}(APIENTRYP PFN{fname.upper()}PROC) ({params});"
                )
                protos.append(f"GLAPI {ret_prefix(ret)}APIENTRY {fname} ({params});")
        out = [f"#ifndef {name}", f"#define {name} 1"] + types + tokens + pfns
        if protos:
            out += ["#ifdef GL_GLEXT_PROTOTYPES"] + protos + ["#endif"]
        out.append(f"#endif /* {name} */")
        return "\n".join(out) + "\n\n"


def vendor_order(name):
    """Mesa's glext.h order: ARB, KHR and OES extensions first, then the rest by name."""
    return ({"ARB": 0, "KHR": 1, "OES": 2}.get(name.split("_")[1], 3), name)


def generate(path):
    """The text of glext.h."""
    reg = Registry(path)
    em = Emitter(reg)
    out = [PREAMBLE.replace("{version}", GLEXT_VERSION), "\n"]
    for f in reg.features:
        if f.get("name") in GL_H_VERSIONS:
            em.mark(f)
        else:
            out.append(em.block(f.get("name"), f))
    exts = {e.get("name"): e for e in reg.extensions}
    exts.update((name, None) for name in EXTRA_EMPTY if name not in exts)
    for name in sorted(exts, key=vendor_order):
        out.append(em.block(name, exts[name]))
    out.append(EPILOGUE)
    return "".join(out)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--check", action="store_true", help="fail if glext.h is stale")
    ap.add_argument("--registry", default=REGISTRY, help="path of gl.xml")
    args = ap.parse_args()
    if not os.path.exists(args.registry):
        sys.exit(f"{args.registry} not found: install khronos-api (scripts/ensure-deps.sh)")
    text = generate(args.registry)
    try:
        with open(OUTPUT) as f:
            current = f.read()
    except FileNotFoundError:
        current = None
    if args.check:
        if current != text:
            sys.exit(f"{OUTPUT} is stale: run `python3 tools/gen_glext.py`")
        return
    if current == text:
        print("unchanged include/GL/glext.h")
        return
    with open(OUTPUT, "w") as f:
        f.write(text)
    print("wrote include/GL/glext.h")


if __name__ == "__main__":
    main()
