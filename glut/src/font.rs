//! GLUT's fonts, from one hand-made sixteen-segment design.
//!
//! Every printable ASCII character is a set of segments on a 2 x 2-cell grid (the
//! layout of sixteen-segment displays, plus two dots). The stroke fonts draw the
//! segments as GL lines, scaled to freeglut's stroke metrics; the bitmap fonts
//! rasterise them into each font's cell size and draw them with `glBitmap` (when the
//! GL provides it). The glyph shapes are softglut's own, not freeglut's; the names,
//! handles and metrics follow freeglut.
//!
//! Font handles are the addresses of the exported data symbols freeglut declares
//! (`glutStrokeRoman`, `glutBitmap8By13`, …). Each holds its font's number, and a
//! handle is recognised by reading that number (an executable's copy-relocated copy
//! holds it too) or, for freeglut's Windows-style small integers, by its value.

#![allow(non_snake_case, non_upper_case_globals)]

use crate::gl::{self, im, GL_LINES};
use std::ffi::{c_char, c_int, c_uchar, c_void, CStr};

/// The number behind a font handle (what the exported symbols hold).
#[repr(C)]
pub struct FontId(usize);

const MAGIC: usize = 0x5067_6c75_7400; // "Pglut\0" tag in the upper bytes.

macro_rules! font_symbols {
    ($($name:ident = $id:expr;)*) => {$(
        /// A GLUT font handle: `GLUT_…` in glut.h is this symbol's address.
        #[no_mangle]
        pub static $name: FontId = FontId(MAGIC + $id);
    )*};
}

font_symbols! {
    glutStrokeRoman = 0;
    glutStrokeMonoRoman = 1;
    glutBitmap9By15 = 2;
    glutBitmap8By13 = 3;
    glutBitmapTimesRoman10 = 4;
    glutBitmapTimesRoman24 = 5;
    glutBitmapHelvetica10 = 6;
    glutBitmapHelvetica12 = 7;
    glutBitmapHelvetica18 = 8;
}

/// Which font a handle names (0..=8 as in freeglut's numbering), if any.
fn font_index(font: *const c_void) -> Option<usize> {
    let addr = font as usize;
    if addr <= 8 {
        return Some(addr);
    }
    if !addr.is_multiple_of(std::mem::align_of::<FontId>()) {
        return None;
    }
    let ours = [
        &glutStrokeRoman,
        &glutStrokeMonoRoman,
        &glutBitmap9By15,
        &glutBitmap8By13,
        &glutBitmapTimesRoman10,
        &glutBitmapTimesRoman24,
        &glutBitmapHelvetica10,
        &glutBitmapHelvetica12,
        &glutBitmapHelvetica18,
    ];
    if let Some(i) = ours.iter().position(|f| std::ptr::eq(*f, font.cast())) {
        return Some(i);
    }
    // SAFETY: GLUT's contract is that a font argument is one of the GLUT_* handles,
    // i.e. the address of one of the FontId symbols above (possibly the executable's
    // copy-relocated copy, which holds the same value); reading one usize is valid.
    let v = unsafe { *font.cast::<usize>() };
    v.checked_sub(MAGIC).filter(|&i| i <= 8)
}

/// Segments of the sixteen-segment grid: x and y in {0, 1, 2} (y up, 0 = baseline).
fn segment(code: u8) -> Option<[(u8, u8); 2]> {
    Some(match code {
        b'a' => [(0, 2), (1, 2)],
        b'A' => [(1, 2), (2, 2)],
        b'b' => [(2, 2), (2, 1)],
        b'c' => [(2, 1), (2, 0)],
        b'd' => [(0, 0), (1, 0)],
        b'D' => [(1, 0), (2, 0)],
        b'e' => [(0, 0), (0, 1)],
        b'f' => [(0, 1), (0, 2)],
        b'g' => [(0, 1), (1, 1)],
        b'G' => [(1, 1), (2, 1)],
        b'h' => [(0, 2), (1, 1)],
        b'i' => [(1, 2), (1, 1)],
        b'j' => [(2, 2), (1, 1)],
        b'k' => [(1, 1), (0, 0)],
        b'l' => [(1, 1), (1, 0)],
        b'm' => [(1, 1), (2, 0)],
        _ => return None,
    })
}

/// The segments of each printable character (' ' to '~'); lower case uses the
/// upper-case shapes. 'p' is a dot on the baseline, 'q' a dot at mid-height.
const GLYPHS: [&str; 95] = [
    "",
    "ip",
    "fi",
    "gGil",
    "aAfgGcdDil",
    "jkaD",
    "aihkdm",
    "i",
    "jm",
    "hk",
    "hijklm",
    "gGil",
    "k",
    "gG",
    "p",
    "jk",
    "aAbcdDefjk",
    "bc",
    "aAbdDegG",
    "aAbcdDG",
    "bcfgG",
    "aAcdDfgG",
    "aAcdDefgG",
    "aAbc",
    "aAbcdDefgG",
    "aAbcdDfgG",
    "pq",
    "qk",
    "jm",
    "gGdD",
    "hk",
    "aAbGp",
    "aAbdDefGi",
    "aAbcefgG",
    "aAbcdDilG",
    "aAdDef",
    "aAbcdDil",
    "aAdDefg",
    "aAefg",
    "aAcdDefG",
    "bcefgG",
    "aAdDil",
    "bcdDe",
    "efgjm",
    "dDef",
    "bcefhj",
    "bcefhm",
    "aAbcdDef",
    "aAbefgG",
    "aAbcdDefm",
    "aAbefgGm",
    "aAcdDfgG",
    "aAil",
    "bcdDef",
    "efkj",
    "bcefkm",
    "hjkm",
    "hjl",
    "aAdDjk",
    "aedf",
    "hm",
    "AbcD",
    "km",
    "dD",
    "h",
    // 'a'..='z' use 'A'..='Z' below; these fill the table's remaining slots.
    "",
    "",
    "",
    "",
    "",
    "",
    "",
    "",
    "",
    "",
    "",
    "",
    "",
    "",
    "",
    "",
    "",
    "",
    "",
    "",
    "",
    "",
    "",
    "",
    "",
    "",
    "aedfg",
    "il",
    "AbcDG",
    "hj",
];

/// Line segments of character `c` in grid units (x, y in 0..=2), dots as short lines.
fn glyph_lines(c: u8) -> Vec<[(f32, f32); 2]> {
    let c = if c.is_ascii_lowercase() {
        c.to_ascii_uppercase()
    } else {
        c
    };
    let Some(codes) = c.checked_sub(b' ').and_then(|i| GLYPHS.get(i as usize)) else {
        return Vec::new();
    };
    codes
        .bytes()
        .filter_map(|code| match code {
            b'p' => Some([(0.9, 0.0), (1.1, 0.0)]),
            b'q' => Some([(0.9, 1.2), (1.1, 1.2)]),
            _ => segment(code).map(|s| {
                [
                    (f32::from(s[0].0), f32::from(s[0].1)),
                    (f32::from(s[1].0), f32::from(s[1].1)),
                ]
            }),
        })
        .collect()
}

/// Stroke metrics (freeglut's): advance of every character, and the font height.
const STROKE_ADVANCE: f32 = 104.76;
const STROKE_HEIGHT: f32 = 152.38;
/// Glyph box inside the advance: x from 14 to 90, y from 0 to 100.
const STROKE_BOX: (f32, f32, f32) = (14.0, 38.0, 50.0);

/// Bitmap fonts: (cell width, cell height, descent rows, advance).
const BITMAP: [(i32, i32, i32, i32); 7] = [
    (9, 15, 3, 9),
    (8, 13, 2, 8),
    (6, 13, 3, 6),
    (13, 28, 6, 13),
    (6, 13, 3, 6),
    (7, 15, 3, 7),
    (10, 22, 5, 10),
];

/// Rasterises character `c` for bitmap font `b`: rows bottom first, bytes MSB first.
fn bitmap_glyph(b: usize, c: u8) -> Vec<u8> {
    let (w, h, descent, _) = BITMAP[b];
    let stride = ((w + 7) / 8) as usize;
    let mut bits = vec![0u8; stride * h as usize];
    let (x0, x1) = (1.0, (w - 2) as f32);
    let (y0, y1) = (descent as f32, (h - 2) as f32);
    let map = |(gx, gy): (f32, f32)| (x0 + (x1 - x0) * gx / 2.0, y0 + (y1 - y0) * gy / 2.0);
    for [a, b2] in glyph_lines(c) {
        let (p, q) = (map(a), map(b2));
        let steps = (q.0 - p.0).abs().max((q.1 - p.1).abs()).ceil().max(1.0) as i32;
        for s in 0..=steps {
            let t = s as f32 / steps as f32;
            let x = (p.0 + (q.0 - p.0) * t).round() as i32;
            let y = (p.1 + (q.1 - p.1) * t).round() as i32;
            if (0..w).contains(&x) && (0..h).contains(&y) {
                bits[y as usize * stride + (x / 8) as usize] |= 0x80 >> (x % 8);
            }
        }
    }
    bits
}

/// `glutBitmapCharacter`: draws at the raster position with glBitmap and advances it.
#[no_mangle]
pub extern "C" fn glutBitmapCharacter(font: *mut c_void, character: c_int) {
    let Some(b) = font_index(font).and_then(|i| i.checked_sub(2)) else {
        return;
    };
    let Some(bitmap) = gl::bitmap_fn() else {
        return;
    };
    let (w, h, descent, adv) = BITMAP[b];
    let bits = bitmap_glyph(b, character as u8);
    let saved = gl::PixelStore::unpack();
    gl::PixelStore::TIGHT.set_unpack();
    // SAFETY: bits holds h rows of ceil(w/8) bytes, what glBitmap reads with the
    // tight unpack state just set.
    unsafe { bitmap(w, h, 0.0, descent as f32, adv as f32, 0.0, bits.as_ptr()) };
    saved.set_unpack();
}

/// `glutBitmapWidth`: the advance of a character.
#[no_mangle]
pub extern "C" fn glutBitmapWidth(font: *mut c_void, _character: c_int) -> c_int {
    font_index(font)
        .and_then(|i| i.checked_sub(2))
        .map_or(0, |b| BITMAP[b].3)
}

/// `glutBitmapHeight` (freeglut): the line height.
#[no_mangle]
pub extern "C" fn glutBitmapHeight(font: *mut c_void) -> c_int {
    font_index(font)
        .and_then(|i| i.checked_sub(2))
        .map_or(0, |b| BITMAP[b].1)
}

/// Length of a NUL-terminated string's characters, or empty for NULL.
fn c_bytes<'a>(s: *const c_uchar) -> &'a [u8] {
    if s.is_null() {
        return &[];
    }
    // SAFETY: GLUT's string functions take NUL-terminated strings; NULL handled above.
    unsafe { CStr::from_ptr(s.cast::<c_char>()) }.to_bytes()
}

/// `glutBitmapLength`: the width of a string in pixels.
#[no_mangle]
pub extern "C" fn glutBitmapLength(font: *mut c_void, string: *const c_uchar) -> c_int {
    c_bytes(string)
        .iter()
        .map(|&c| glutBitmapWidth(font, c_int::from(c)))
        .sum()
}

/// `glutBitmapString` (freeglut).
#[no_mangle]
pub extern "C" fn glutBitmapString(font: *mut c_void, string: *const c_uchar) {
    for &c in c_bytes(string) {
        glutBitmapCharacter(font, c_int::from(c));
    }
}

/// `glutStrokeCharacter`: draws the character as lines and translates by its advance.
#[no_mangle]
pub extern "C" fn glutStrokeCharacter(font: *mut c_void, character: c_int) {
    if !matches!(font_index(font), Some(0 | 1)) {
        return;
    }
    let (x0, sx, sy) = STROKE_BOX;
    let lines = glyph_lines(character as u8);
    if !lines.is_empty() {
        im::begin(GL_LINES);
        for [a, b] in lines {
            im::v2(x0 + a.0 * sx, a.1 * sy);
            im::v2(x0 + b.0 * sx, b.1 * sy);
        }
        im::end();
    }
    im::translate(STROKE_ADVANCE, 0.0, 0.0);
}

/// `glutStrokeWidth`.
#[no_mangle]
pub extern "C" fn glutStrokeWidth(font: *mut c_void, _character: c_int) -> c_int {
    if matches!(font_index(font), Some(0 | 1)) {
        STROKE_ADVANCE as c_int
    } else {
        0
    }
}

/// `glutStrokeWidthf` (freeglut).
#[no_mangle]
pub extern "C" fn glutStrokeWidthf(font: *mut c_void, _character: c_int) -> f32 {
    if matches!(font_index(font), Some(0 | 1)) {
        STROKE_ADVANCE
    } else {
        0.0
    }
}

/// `glutStrokeLength`.
#[no_mangle]
pub extern "C" fn glutStrokeLength(font: *mut c_void, string: *const c_uchar) -> c_int {
    c_bytes(string)
        .iter()
        .map(|&c| glutStrokeWidth(font, c_int::from(c)))
        .sum()
}

/// `glutStrokeHeight` (freeglut).
#[no_mangle]
pub extern "C" fn glutStrokeHeight(font: *mut c_void) -> f32 {
    if matches!(font_index(font), Some(0 | 1)) {
        STROKE_HEIGHT
    } else {
        0.0
    }
}

/// `glutStrokeString` (freeglut): a newline returns to the string's start, one line down.
#[no_mangle]
pub extern "C" fn glutStrokeString(font: *mut c_void, string: *const c_uchar) {
    let mut x = 0.0;
    for &c in c_bytes(string) {
        if c == b'\n' {
            im::translate(-x, -STROKE_HEIGHT, 0.0);
            x = 0.0;
        } else {
            glutStrokeCharacter(font, c_int::from(c));
            x += STROKE_ADVANCE;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn handles_resolve() {
        let p = &glutBitmap8By13 as *const FontId as *mut c_void;
        assert_eq!(font_index(p), Some(3));
        assert_eq!(font_index(3 as *mut c_void), Some(3));
        assert_eq!(glutBitmapWidth(p, i32::from(b'A')), 8);
        assert!(!glyph_lines(b'A').is_empty());
        assert_eq!(glyph_lines(b'a'), glyph_lines(b'A'));
        assert!(bitmap_glyph(1, b'H').iter().any(|&b| b != 0));
    }
}
