#!/usr/bin/env python3
"""Writes c_tests/begin_end_calls.h: one call with sane arguments for every GL entry point
softgl exports (every prototype in include/GL/gl.h and glext.h that the built
libsoftgl.so defines; glext.h declares every function of the registry), for the
begin_end_errors scene. Run from the repository root after adding entry points and
building the library:

    python3 tools/gen_begin_end_calls.py [path/to/libsoftgl.so]

Each entry is `CALL(name, kind, expr)`: `kind` says how to print the value `expr` returns
(V void, N number, P pointer). Arguments come from the parameter's type and name, with the
per-function choices below: valid enums, client memory the scene owns, names of objects
the scene made (2 is a name no object has; 1 is the scene's texture, buffer, list).
"""

import re
import subprocess
import sys

# glEnd closes the pair the scene opens, so it is not one of the calls.
SKIP = {"glEnd"}

# Enum arguments by parameter name, then per function (first match of a regex wins).
ENUM_BY_FUNC = [
    (r"glHint$", {"target": "GL_PERSPECTIVE_CORRECTION_HINT", "mode": "GL_NICEST"}),
    (r"glShadeModel", {"mode": "GL_FLAT"}),
    (r"glCullFace", {"mode": "GL_FRONT"}),
    (r"glFrontFace", {"mode": "GL_CW"}),
    (r"glMatrixMode", {"mode": "GL_PROJECTION"}),
    (r"glBegin", {"mode": "GL_POINTS"}),
    (r"glBlendEquation(EXT)?$", {"mode": "GL_MIN"}),
    (r"glColorMaterial", {"mode": "GL_DIFFUSE"}),
    (r"glPolygonMode", {"mode": "GL_LINE"}),
    (r"glNewList", {"mode": "GL_COMPILE"}),
    (r"glRenderMode", {"mode": "GL_RENDER"}),
    (r"glEvalMesh", {"mode": "GL_POINT"}),
    (r"glDrawBuffer", {"mode": "GL_NONE"}),
    (r"glReadBuffer", {"mode": "GL_FRONT"}),
    (r"glEnableClientState|glDisableClientState", {"cap": "GL_COLOR_ARRAY"}),
    (r"glInterleavedArrays", {"format": "GL_V2F"}),
    (r"glCompressedTex", {"format": "0x83F1",
                          "internalformat": "0x83F1"}),
    (r"glRenderbufferStorage", {"internalformat": "GL_RGBA8"}),
    (r"glCopyPixels", {"type": "GL_COLOR"}),
    (r"glFeedbackBuffer", {"type": "GL_2D"}),
    (r"Pointer(EXT)?$", {"type": "GL_FLOAT"}),
    (r"glPixelStore", {"pname": "GL_UNPACK_ALIGNMENT"}),
    (r"glGet(Boolean|Integer|Float|Double)v", {"pname": "GL_VIEWPORT"}),
    (r"glGetPointerv", {"pname": "GL_VERTEX_ARRAY_POINTER"}),
    (r"glTexParameter[fi]$", {"pname": "GL_TEXTURE_PRIORITY"}),
    (r"glTexParameter", {"pname": "GL_TEXTURE_BORDER_COLOR"}),
    (r"glGetTexParameter", {"pname": "GL_TEXTURE_MIN_FILTER"}),
    (r"glGetTexLevelParameter", {"pname": "GL_TEXTURE_WIDTH"}),
    (r"glTexEnv[fi]$", {"pname": "GL_TEXTURE_ENV_MODE"}),
    (r"TexEnv", {"target": "GL_TEXTURE_ENV", "pname": "GL_TEXTURE_ENV_COLOR"}),
    (r"glLight[fi]$", {"pname": "GL_SPOT_EXPONENT"}),
    (r"glLightModel[fi]$", {"pname": "GL_LIGHT_MODEL_TWO_SIDE"}),
    (r"glLightModel", {"pname": "GL_LIGHT_MODEL_AMBIENT"}),
    (r"Light", {"pname": "GL_DIFFUSE"}),
    (r"glMaterial[fi]$", {"pname": "GL_SHININESS"}),
    (r"Material", {"pname": "GL_DIFFUSE", "face": "GL_FRONT"}),
    (r"glFog[fi]$", {"pname": "GL_FOG_DENSITY"}),
    (r"glFog", {"pname": "GL_FOG_COLOR"}),
    (r"glTexGen[fid]$", {"pname": "GL_TEXTURE_GEN_MODE"}),
    (r"TexGen", {"pname": "GL_OBJECT_PLANE"}),
    (r"glPixelTransfer", {"pname": "GL_RED_SCALE"}),
    (r"ColorTableParameter", {"pname": "GL_COLOR_TABLE_SCALE"}),
    (r"glConvolutionParameter[fi]$", {"pname": "GL_CONVOLUTION_BORDER_MODE"}),
    (r"ConvolutionParameter", {"pname": "GL_CONVOLUTION_FILTER_SCALE"}),
    (r"HistogramParameter", {"pname": "GL_HISTOGRAM_WIDTH"}),
    (r"MinmaxParameter", {"pname": "GL_MINMAX_FORMAT"}),
    (r"glGetBufferPointerv", {"pname": "GL_BUFFER_MAP_POINTER"}),
    (r"glGetBufferParameter", {"pname": "GL_BUFFER_SIZE"}),
    (r"glGetRenderbufferParameter", {"pname": "GL_RENDERBUFFER_WIDTH"}),
    (r"glGetFramebufferAttachmentParameter",
     {"pname": "GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE"}),
    (r"glPointParameter[fi](ARB|EXT)?$", {"pname": "GL_POINT_SIZE_MIN"}),
    (r"glPointParameter", {"pname": "GL_POINT_DISTANCE_ATTENUATION"}),
    (r"glGetQueryiv", {"pname": "GL_CURRENT_QUERY"}),
    (r"glGetQueryObject", {"pname": "GL_QUERY_RESULT_AVAILABLE"}),
    (r"1D", {"target": "GL_TEXTURE_1D", "textarget": "GL_TEXTURE_1D"}),
    (r"3D", {"target": "GL_TEXTURE_3D", "textarget": "GL_TEXTURE_3D"}),
    (r"glMap1|glGetMap", {"target": "GL_MAP1_VERTEX_3"}),
    (r"glMap2", {"target": "GL_MAP2_VERTEX_3"}),
    (r"MultiTexCoord", {"target": "GL_TEXTURE0"}),
    (r"ColorTable|ColorSubTable", {"target": "GL_COLOR_TABLE"}),
    (r"Convolution", {"target": "GL_CONVOLUTION_2D"}),
    (r"Separable", {"target": "GL_SEPARABLE_2D"}),
    (r"Histogram", {"target": "GL_HISTOGRAM"}),
    (r"Minmax", {"target": "GL_MINMAX"}),
    (r"Buffer(Data|SubData|Parameteriv|Pointerv|ARB)|glBindBuffer|MapBuffer",
     {"target": "GL_ARRAY_BUFFER"}),
    (r"Framebuffer(Texture|Renderbuffer|Status|Attachment)|glBindFramebuffer",
     {"target": "GL_FRAMEBUFFER"}),
    (r"Renderbuffer", {"target": "GL_RENDERBUFFER"}),
    (r"Query", {"target": "GL_SAMPLES_PASSED"}),
    (r"Draw(Range)?Elements|DrawArrays", {"mode": "GL_TRIANGLES", "type": "GL_UNSIGNED_BYTE"}),
]

ENUM_BY_NAME = {
    "access": "GL_READ_ONLY", "attachment": "GL_COLOR_ATTACHMENT0", "cap": "GL_BLEND",
    "coord": "GL_S", "depth": "GL_ZERO_TO_ONE", "origin": "GL_UPPER_LEFT",
    "sfactor": "GL_ONE", "dfactor": "GL_ONE", "sfactorRGB": "GL_ONE",
    "dfactorRGB": "GL_ONE", "sfactorAlpha": "GL_ONE", "dfactorAlpha": "GL_ONE",
    "fail": "GL_INCR", "zfail": "GL_INCR", "zpass": "GL_INCR", "sfail": "GL_INCR",
    "dpfail": "GL_INCR", "dppass": "GL_INCR", "face": "GL_FRONT_AND_BACK",
    "filter": "GL_NEAREST", "format": "GL_RGBA", "func": "GL_GREATER",
    "internalformat": "GL_RGBA", "light": "GL_LIGHT0", "map": "GL_PIXEL_MAP_R_TO_R",
    "modeRGB": "GL_FUNC_REVERSE_SUBTRACT", "modeAlpha": "GL_FUNC_REVERSE_SUBTRACT",
    "name": "GL_VENDOR", "op": "GL_RETURN", "opcode": "GL_XOR", "plane": "GL_CLIP_PLANE0",
    "query": "GL_ORDER", "renderbuffertarget": "GL_RENDERBUFFER",
    "textarget": "GL_TEXTURE_2D", "texture": "GL_TEXTURE1", "type": "GL_UNSIGNED_BYTE",
    "types": "GL_UNSIGNED_BYTE", "usage": "GL_STATIC_DRAW", "target": "GL_TEXTURE_2D",
}

# Integer arguments by parameter name (GLint, GLsizei, GLuint …); others are 1.
INT_BY_NAME = {
    "x": 0, "y": 0, "z": 0, "level": 0, "border": 0, "xoffset": 0, "yoffset": 0,
    "zoffset": 0, "first": 0, "start": 0, "end": 2, "count": 3, "stride": 0, "size": 3,
    "i": 3, "list": 1, "base": 5, "ustride": 3, "vstride": 6, "uorder": 2, "vorder": 2,
    "order": 2, "i1": 0, "i2": 1, "j1": 0, "j2": 1, "pattern": 0xF0F0, "samples": 0,
    "texture": 2, "buffer": 2, "framebuffer": 2, "renderbuffer": 2, "id": 2,
    "image_size": 8, "imageSize": 8, "srcX0": 0, "srcY0": 0, "srcX1": 1, "srcY1": 1,
    "dstX0": 2, "dstY0": 2, "dstX1": 3, "dstY1": 3, "mask": 0, "layer": 0,
}

# Whole argument lists for calls the rules above would get wrong.
ARGS = {
    "glNewList": "5, GL_COMPILE",
    "glDeleteLists": "1, 1",
    "glIsList": "1",
    "glGenLists": "1",
    "glCallLists": "1, GL_UNSIGNED_BYTE, cub",
    "glPushAttrib": "GL_ALL_ATTRIB_BITS",
    "glPushClientAttrib": "GL_CLIENT_ALL_ATTRIB_BITS",
    "glClear": "GL_COLOR_BUFFER_BIT",
    "glBufferData": "GL_ARRAY_BUFFER, 4, cub, GL_STATIC_DRAW",
    "glBufferDataARB": "GL_ARRAY_BUFFER, 4, cub, GL_STATIC_DRAW",
    "glFeedbackBuffer": "16, GL_2D, (GLfloat *)ob",
    "glSelectBuffer": "16, (GLuint *)ob",
    "glTexEnvf": "GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, (GLfloat)GL_ADD",
    "glTexEnvi": "GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_ADD",
    "glTexGenf": "GL_S, GL_TEXTURE_GEN_MODE, (GLfloat)GL_OBJECT_LINEAR",
    "glTexGend": "GL_S, GL_TEXTURE_GEN_MODE, (GLdouble)GL_OBJECT_LINEAR",
    "glTexGeni": "GL_S, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR",
    "glConvolutionParameterf": "GL_CONVOLUTION_2D, GL_CONVOLUTION_BORDER_MODE, (GLfloat)GL_REDUCE",
    "glConvolutionParameteri": "GL_CONVOLUTION_2D, GL_CONVOLUTION_BORDER_MODE, GL_REDUCE",
    "glLightModeli": "GL_LIGHT_MODEL_TWO_SIDE, 1",
    "glDrawRangeElements": "GL_TRIANGLES, 0, 2, 3, GL_UNSIGNED_BYTE, idx",
    "glDrawRangeElementsEXT": "GL_TRIANGLES, 0, 2, 3, GL_UNSIGNED_BYTE, idx",
    "glDrawElements": "GL_TRIANGLES, 3, GL_UNSIGNED_BYTE, idx",
    "glMultiDrawArrays": "GL_TRIANGLES, cfirst, ccount, 1",
    "glMultiDrawArraysEXT": "GL_TRIANGLES, cfirst, ccount, 1",
    "glMultiDrawElements": "GL_TRIANGLES, ccount, GL_UNSIGNED_BYTE, idxp, 1",
    "glMultiDrawElementsEXT": "GL_TRIANGLES, ccount, GL_UNSIGNED_BYTE, idxp, 1",
    "glBlitFramebuffer": "0, 0, 1, 1, 2, 2, 3, 3, GL_COLOR_BUFFER_BIT, GL_NEAREST",
    "glBlitFramebufferEXT": "0, 0, 1, 1, 2, 2, 3, 3, GL_COLOR_BUFFER_BIT, GL_NEAREST",
    "glViewport": "0, 0, 3, 3",
    "glScissor": "0, 0, 3, 3",
    "glLineStipple": "1, 0xF0F0",
    "glGetTexImage": "GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, ob",
}

# Entry points Mesa's libOSMesa does not export as symbols: called through
# OSMesaGetProcAddress, as programs must call them there.
BY_PROC = {"glBlendEquationSeparateEXT", "glBlitFramebufferEXT", "glClipControl"}

# Float arguments: vertices land off the viewport; others are 0.5.
OFFSCREEN = re.compile(r"glVertex[234]")
RECT = re.compile(r"glRect[sifd]v?$")


def pointer_arg(func, ptype, pname):
    base = ptype.replace("const", "").replace("*", "").strip()
    const = "const" in ptype
    if ptype.count("*") == 2:
        return "idxp" if "const" in ptype else "&pp"
    if not const:
        return f"({base} *)ob"
    if pname == "indices":
        return "idx"
    if RECT.match(func):
        return {"v1": "rect_lo", "v2": "rect_hi"}[pname] + "_" + base[2:]
    if OFFSCREEN.match(func):
        return "off_" + base[2:]
    if base in ("GLvoid", "void", "GLubyte", "GLbyte", "GLboolean"):
        return f"(const {base} *)cub"
    return "c_" + {"GLclampf": "float", "GLclampd": "double"}.get(base, base[2:])


def scalar_arg(func, ptype, pname, enum_map):
    if ptype == "GLenum":
        return enum_map.get(pname) or ENUM_BY_NAME.get(pname) or "GL_TEXTURE_2D"
    if ptype == "GLbitfield":
        return "GL_COLOR_BUFFER_BIT"
    if ptype == "GLboolean":
        return "GL_FALSE"
    if RECT.match(func):
        return {"x1": "-1", "y1": "-1", "x2": "1", "y2": "1"}[pname]
    if ptype in ("GLfloat", "GLdouble", "GLclampf", "GLclampd"):
        return "2" if OFFSCREEN.match(func) else "0.5"
    return str(INT_BY_NAME.get(pname, 1))


def exports(lib):
    """The gl* functions the library defines (nm -D --defined-only)."""
    out = subprocess.run(["nm", "-D", "--defined-only", lib], capture_output=True, text=True,
                         check=True).stdout
    return {line.split()[-1] for line in out.splitlines() if line.split()[-1].startswith("gl")}


def main():
    lib = sys.argv[1] if len(sys.argv) > 1 else "target/release/libsoftgl.so"
    exported = exports(lib)
    txt = open("include/GL/gl.h").read() + open("include/GL/glext.h").read()
    protos = re.findall(
        r"GLAPI\s+([^;]*?)\s*(?:GLAPIENTRY|APIENTRY)\s*\*?\s*(gl\w+)\s*\(([^)]*)\)\s*;", txt)
    out = ["/* Generated by tools/gen_begin_end_calls.py from include/GL/{gl,glext}.h: do not"
           " edit. */"]
    seen = set()
    for ret, name, params in protos:
        if name in SKIP or name in seen or name not in exported:
            continue
        seen.add(name)
        ret = ret.replace("GLAPI", "").strip()
        kind = "V" if ret == "void" else ("P" if "*" in ret or name in ("glGetString",
                                                                       "glMapBuffer") else "N")
        if name in ARGS:
            args = ARGS[name]
        else:
            enum_map = {}
            for pat, m in ENUM_BY_FUNC:
                if re.search(pat, name):
                    for k, v in m.items():
                        enum_map.setdefault(k, v)
            args = []
            for p in params.split(","):
                p = p.strip()
                if p in ("void", ""):
                    continue
                m = re.match(r"(.*?)(\w+)$", p)
                ptype, pname = m.group(1).strip(), m.group(2)
                if "*" in ptype:
                    args.append(pointer_arg(name, ptype, pname))
                else:
                    args.append(scalar_arg(name, ptype, pname, enum_map))
            args = ", ".join(args)
        fn = name
        if name in BY_PROC:
            fn = f'((PFN{name.upper()}PROC)OSMesaGetProcAddress("{name}"))'
        out.append(f"CALL({name}, {kind}, {fn}({args}))")
    open("c_tests/begin_end_calls.h", "w").write("\n".join(out) + "\n")
    print(f"{len(seen)} entry points", file=sys.stderr)


if __name__ == "__main__":
    main()
