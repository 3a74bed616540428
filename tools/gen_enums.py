#!/usr/bin/env python3
"""Regenerates src/gl/enums.rs and src/gl/glext_enums.rs from the Khronos/Mesa headers
installed on a Debian machine (/usr/include/GL/gl.h and glext.h).

The enum values are part of the OpenGL ABI, so we take them from the reference headers
instead of typing them by hand. enums.rs (which makes our gl.h's tokens) gets every token of
Mesa's gl.h (GL 1.0-1.3 and the extensions it declares); glext_enums.rs gets the GL 1.4/1.5
tokens and the ARB/EXT extensions that softgl advertises or that programs commonly test for,
for use in Rust only: include/GL/glext.h comes from the Khronos registry
(tools/gen_glext.py), and tests/headers.rs checks these values against it. Run once; the
output is committed.
"""
import re, sys

GL_H = "/usr/include/GL/gl.h"
GLEXT_H = "/usr/include/GL/glext.h"

EXTS = """GL_VERSION_1_4 GL_VERSION_1_5 GL_ARB_depth_texture GL_ARB_occlusion_query
GL_ARB_point_parameters GL_ARB_shadow GL_ARB_texture_border_clamp GL_ARB_texture_env_add
GL_ARB_texture_env_combine GL_ARB_texture_env_crossbar GL_ARB_texture_env_dot3
GL_ARB_texture_mirrored_repeat GL_ARB_transpose_matrix GL_ARB_vertex_buffer_object
GL_ARB_window_pos GL_EXT_abgr GL_EXT_bgra GL_EXT_blend_color GL_EXT_blend_func_separate
GL_EXT_blend_minmax GL_EXT_blend_subtract GL_EXT_draw_range_elements GL_EXT_fog_coord
GL_EXT_multi_draw_arrays GL_EXT_packed_pixels GL_EXT_point_parameters GL_EXT_rescale_normal
GL_EXT_secondary_color GL_EXT_separate_specular_color GL_EXT_stencil_wrap GL_EXT_texture3D
GL_EXT_texture_env_add GL_EXT_texture_env_combine GL_EXT_texture_filter_anisotropic
GL_EXT_texture_lod_bias GL_NV_blend_square GL_SGIS_generate_mipmap
GL_SGIS_texture_edge_clamp GL_ARB_texture_cube_map GL_ARB_framebuffer_object
GL_EXT_framebuffer_object GL_EXT_framebuffer_blit GL_EXT_framebuffer_multisample
GL_EXT_packed_depth_stencil GL_ARB_clip_control GL_EXT_texture_sRGB
GL_EXT_texture_compression_s3tc GL_ARB_texture_compression_rgtc GL_EXT_texture_compression_rgtc
GL_EXT_texture_compression_latc GL_ATI_texture_compression_3dc
GL_ARB_texture_float GL_ARB_half_float_pixel GL_ARB_texture_rg
GL_ARB_framebuffer_sRGB GL_EXT_framebuffer_sRGB GL_ARB_pixel_buffer_object
GL_EXT_pixel_buffer_object""".split()

# Tokens of an extension that glext.h lists under the GL version that took it into core
# (GL_ARB_clip_control's under GL_VERSION_4_5; GL_LOWER_LEFT/GL_UPPER_LEFT under 2.0):
# emitted inside the extension's own section.
SECTION_TOKENS = {
    "GL_ARB_clip_control": """GL_LOWER_LEFT GL_UPPER_LEFT GL_NEGATIVE_ONE_TO_ONE GL_ZERO_TO_ONE
GL_CLIP_ORIGIN GL_CLIP_DEPTH_MODE""".split(),
    "GL_ARB_texture_compression_rgtc": """GL_COMPRESSED_RED_RGTC1 GL_COMPRESSED_SIGNED_RED_RGTC1
GL_COMPRESSED_RG_RGTC2 GL_COMPRESSED_SIGNED_RG_RGTC2""".split(),
    # GL 3.0's names of the formats and type (the core section lists them)
    "GL_ARB_texture_float": "GL_RGBA32F GL_RGB32F GL_RGBA16F GL_RGB16F".split(),
    "GL_ARB_half_float_pixel": ["GL_HALF_FLOAT"],
    "GL_ARB_texture_rg": """GL_RG GL_RG_INTEGER GL_R8 GL_R16 GL_RG8 GL_RG16 GL_R16F GL_R32F
GL_RG16F GL_RG32F""".split(),
    # GL 3.0's name of the enable (the core section lists it)
    "GL_ARB_framebuffer_sRGB": ["GL_FRAMEBUFFER_SRGB"],
    # GL 2.1's names of the pixel buffer targets and bindings
    "GL_ARB_pixel_buffer_object": """GL_PIXEL_PACK_BUFFER GL_PIXEL_UNPACK_BUFFER
GL_PIXEL_PACK_BUFFER_BINDING GL_PIXEL_UNPACK_BUFFER_BINDING""".split(),
}

# Single tokens from later GL versions that GL 1.5 programs use with functions Mesa exports
# (separate blend equation and separate stencil state are GL 2.0), and GL 2.0's shader
# limits, hint and strings, which the GL 2.1 context answers.
EXTRA_TOKENS = """GL_BLEND_EQUATION_RGB GL_BLEND_EQUATION_ALPHA GL_STENCIL_BACK_FUNC GL_STENCIL_BACK_FAIL
GL_STENCIL_BACK_PASS_DEPTH_FAIL GL_STENCIL_BACK_PASS_DEPTH_PASS GL_STENCIL_BACK_REF
GL_STENCIL_BACK_VALUE_MASK GL_STENCIL_BACK_WRITEMASK GL_MAX_TEXTURE_IMAGE_UNITS
GL_MAX_TEXTURE_COORDS GL_MAX_VARYING_FLOATS GL_MAX_VERTEX_UNIFORM_COMPONENTS
GL_MAX_FRAGMENT_UNIFORM_COMPONENTS GL_MAX_VERTEX_TEXTURE_IMAGE_UNITS
GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS GL_FRAGMENT_SHADER_DERIVATIVE_HINT
GL_SHADING_LANGUAGE_VERSION GL_SHADER_COMPILER""".split()

# GL 2.1's sRGB texture formats (GL_EXT_texture_sRGB without the suffix), which programs
# pass whether or not the extension is advertised.
SRGB_TOKENS = """GL_SRGB GL_SRGB8 GL_SRGB_ALPHA GL_SRGB8_ALPHA8 GL_SLUMINANCE_ALPHA
GL_SLUMINANCE8_ALPHA8 GL_SLUMINANCE GL_SLUMINANCE8 GL_COMPRESSED_SRGB GL_COMPRESSED_SRGB_ALPHA
GL_COMPRESSED_SLUMINANCE GL_COMPRESSED_SLUMINANCE_ALPHA""".split()

# GL_ARB_framebuffer_object's tokens, which glext.h lists under GL_VERSION_3_0.
FBO_TOKENS = """GL_INVALID_FRAMEBUFFER_OPERATION GL_FRAMEBUFFER_ATTACHMENT_COLOR_ENCODING GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE GL_FRAMEBUFFER_ATTACHMENT_RED_SIZE
GL_FRAMEBUFFER_ATTACHMENT_GREEN_SIZE GL_FRAMEBUFFER_ATTACHMENT_BLUE_SIZE GL_FRAMEBUFFER_ATTACHMENT_ALPHA_SIZE GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE
GL_FRAMEBUFFER_ATTACHMENT_STENCIL_SIZE GL_FRAMEBUFFER_DEFAULT GL_FRAMEBUFFER_UNDEFINED GL_DEPTH_STENCIL_ATTACHMENT
GL_MAX_RENDERBUFFER_SIZE GL_DEPTH_STENCIL GL_UNSIGNED_INT_24_8 GL_DEPTH24_STENCIL8
GL_TEXTURE_STENCIL_SIZE GL_TEXTURE_RED_TYPE GL_TEXTURE_GREEN_TYPE GL_TEXTURE_BLUE_TYPE
GL_TEXTURE_ALPHA_TYPE GL_TEXTURE_DEPTH_TYPE GL_UNSIGNED_NORMALIZED GL_FRAMEBUFFER_BINDING
GL_DRAW_FRAMEBUFFER_BINDING GL_RENDERBUFFER_BINDING GL_READ_FRAMEBUFFER GL_DRAW_FRAMEBUFFER
GL_READ_FRAMEBUFFER_BINDING GL_RENDERBUFFER_SAMPLES GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME
GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LEVEL GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_CUBE_MAP_FACE GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LAYER GL_FRAMEBUFFER_COMPLETE
GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER
GL_FRAMEBUFFER_UNSUPPORTED GL_MAX_COLOR_ATTACHMENTS GL_COLOR_ATTACHMENT0 GL_COLOR_ATTACHMENT1
GL_COLOR_ATTACHMENT2 GL_COLOR_ATTACHMENT3 GL_COLOR_ATTACHMENT4 GL_COLOR_ATTACHMENT5
GL_COLOR_ATTACHMENT6 GL_COLOR_ATTACHMENT7 GL_COLOR_ATTACHMENT8 GL_COLOR_ATTACHMENT9
GL_COLOR_ATTACHMENT10 GL_COLOR_ATTACHMENT11 GL_COLOR_ATTACHMENT12 GL_COLOR_ATTACHMENT13
GL_COLOR_ATTACHMENT14 GL_COLOR_ATTACHMENT15 GL_COLOR_ATTACHMENT16 GL_COLOR_ATTACHMENT17
GL_COLOR_ATTACHMENT18 GL_COLOR_ATTACHMENT19 GL_COLOR_ATTACHMENT20 GL_COLOR_ATTACHMENT21
GL_COLOR_ATTACHMENT22 GL_COLOR_ATTACHMENT23 GL_COLOR_ATTACHMENT24 GL_COLOR_ATTACHMENT25
GL_COLOR_ATTACHMENT26 GL_COLOR_ATTACHMENT27 GL_COLOR_ATTACHMENT28 GL_COLOR_ATTACHMENT29
GL_COLOR_ATTACHMENT30 GL_COLOR_ATTACHMENT31 GL_DEPTH_ATTACHMENT GL_STENCIL_ATTACHMENT
GL_FRAMEBUFFER GL_RENDERBUFFER GL_RENDERBUFFER_WIDTH GL_RENDERBUFFER_HEIGHT
GL_RENDERBUFFER_INTERNAL_FORMAT GL_STENCIL_INDEX1 GL_STENCIL_INDEX4 GL_STENCIL_INDEX8
GL_STENCIL_INDEX16 GL_RENDERBUFFER_RED_SIZE GL_RENDERBUFFER_GREEN_SIZE GL_RENDERBUFFER_BLUE_SIZE
GL_RENDERBUFFER_ALPHA_SIZE GL_RENDERBUFFER_DEPTH_SIZE GL_RENDERBUFFER_STENCIL_SIZE GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE
GL_MAX_SAMPLES GL_INDEX GL_TEXTURE_LUMINANCE_TYPE GL_TEXTURE_INTENSITY_TYPE""".split()

# GL 3.0/3.2 tokens of extensions softgl advertises whose glext.h sections are empty
# (GL_ARB_depth_buffer_float, GL_ARB_seamless_cube_map: their tokens sit in the core
# version sections).
CORE_EXT_TOKENS = """GL_DEPTH_COMPONENT32F GL_DEPTH32F_STENCIL8 GL_FLOAT_32_UNSIGNED_INT_24_8_REV
GL_TEXTURE_CUBE_MAP_SEAMLESS""".split()

DEF = re.compile(r"^#define\s+(GL_\w+)\s+(0x[0-9A-Fa-f]+|\d+)u?\s*$")


def tokens(lines):
    out = []
    for line in lines:
        m = DEF.match(line.strip())
        if m:
            out.append((m.group(1), m.group(2)))
    return out


def rust(name, value):
    return f"pub const {name}: GLenum = {value};"


def main():
    gl = open(GL_H).read().splitlines()
    seen = set()
    body = []
    for name, value in tokens(gl):
        if name in seen or name.startswith("GL_GLEXT"):
            continue
        seen.add(name)
        body.append(rust(name, value))
    with open("src/gl/enums.rs", "w") as f:
        f.write("//! The tokens of `GL/gl.h` (GL 1.0-1.3): every enum value a C program may pass.\n")
        f.write("//! Generated by `tools/gen_enums.py` from Mesa's gl.h; do not edit by hand.\n")
        f.write("#![allow(missing_docs, non_upper_case_globals)]\n\nuse super::types::GLenum;\n\n")
        f.write("\n".join(body) + "\n")

    ext = open(GLEXT_H).read().splitlines()
    body = []
    section = None
    depth = 0
    for line in ext:
        s = line.strip()
        if section is None:
            m = re.match(r"^#ifndef\s+(GL_\w+)$", s)
            if m and m.group(1) in EXTS:
                section = m.group(1)
                depth = 0
                body.append(f"\n// {section}")
            continue
        if s.startswith("#if"):
            depth += 1
            continue
        if s.startswith("#endif"):
            if depth == 0:
                for name in SECTION_TOKENS.get(section, []):
                    value = next(m.group(2) for m in map(DEF.match, map(str.strip, ext))
                                 if m and m.group(1) == name)
                    if name not in seen:
                        seen.add(name)
                        body.append(rust(name, value))
                section = None
            else:
                depth -= 1
            continue
        if depth > 0:
            continue
        m = DEF.match(s)
        if m and m.group(1) not in seen:
            seen.add(m.group(1))
            body.append(rust(m.group(1), m.group(2)))
    listed = [
        ("Single GL 2.0 tokens, and GL_ARB_framebuffer_object's (GL 3.0's section)",
         EXTRA_TOKENS + FBO_TOKENS),
        ("GL 2.1's sRGB texture formats", SRGB_TOKENS),
        ("GL_ARB_depth_buffer_float and GL_ARB_seamless_cube_map (core-section tokens)",
         CORE_EXT_TOKENS),
    ]
    for title, names in listed:
        body.append(f"\n// {title}")
        for line in ext:
            m = DEF.match(line.strip())
            if m and m.group(1) in names and m.group(1) not in seen:
                seen.add(m.group(1))
                body.append(rust(m.group(1), m.group(2)))
    with open("src/gl/glext_enums.rs", "w") as f:
        f.write("//! The tokens of `GL/glext.h`: GL 1.4/1.5 and the ARB/EXT extensions programs test for.\n")
        f.write("//! Generated by `tools/gen_enums.py` from Mesa's glext.h; do not edit by hand.\n")
        f.write("#![allow(missing_docs, non_upper_case_globals)]\n\nuse super::types::GLenum;\n")
        f.write("\n".join(body) + "\n")


if __name__ == "__main__":
    sys.exit(main())
