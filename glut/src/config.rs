//! The environment variables that configure a headless run.

use std::path::PathBuf;

/// A keystroke fed to the keyboard (or special-key) callback before a frame.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Key {
    /// An ASCII key for `glutKeyboardFunc`.
    Ascii(u8),
    /// A `GLUT_KEY_*` code for `glutSpecialFunc`.
    Special(i32),
}

/// What `SOFTGLUT_*` asks for.
#[derive(Clone, Debug)]
pub struct Config {
    /// `SOFTGLUT_FRAMES`: frames displayed and written (default 1).
    pub frames: u32,
    /// `SOFTGLUT_OUTPUT`: folder for the PNG files (default: the current folder).
    pub output: PathBuf,
    /// `SOFTGLUT_SIZE=WxH`: overrides every window's size.
    pub size: Option<(i32, i32)>,
    /// `SOFTGLUT_KEYS=FRAME:KEY,...`: keystrokes delivered before the given frame.
    pub keys: Vec<(u32, Key)>,
    /// `SOFTGLUT_STEP_MS`: milliseconds the GLUT clock advances per frame (default 20).
    pub step_ms: i32,
}

/// The special keys `SOFTGLUT_KEYS` knows by name, with their `GLUT_KEY_*` codes.
const SPECIAL: [(&str, i32); 20] = [
    ("F1", 1),
    ("F2", 2),
    ("F3", 3),
    ("F4", 4),
    ("F5", 5),
    ("F6", 6),
    ("F7", 7),
    ("F8", 8),
    ("F9", 9),
    ("F10", 10),
    ("F11", 11),
    ("F12", 12),
    ("LEFT", 0x64),
    ("UP", 0x65),
    ("RIGHT", 0x66),
    ("DOWN", 0x67),
    ("PAGE_UP", 0x68),
    ("PAGE_DOWN", 0x69),
    ("HOME", 0x6A),
    ("END", 0x6B),
];

/// ASCII keys with names (characters awkward in the list syntax).
const NAMED_ASCII: [(&str, u8); 7] = [
    ("ESC", 27),
    ("SPACE", b' '),
    ("ENTER", b'\r'),
    ("TAB", b'\t'),
    ("BACKSPACE", 8),
    ("DELETE", 127),
    ("COMMA", b','),
];

/// Parses one key: a single character, or a name from the tables above.
pub fn parse_key(s: &str) -> Option<Key> {
    if s.len() == 1 {
        return Some(Key::Ascii(s.as_bytes()[0]));
    }
    let up = s.to_ascii_uppercase();
    if let Some(&(_, c)) = NAMED_ASCII.iter().find(|(n, _)| *n == up) {
        return Some(Key::Ascii(c));
    }
    SPECIAL
        .iter()
        .find(|(n, _)| *n == up)
        .map(|&(_, c)| Key::Special(c))
}

/// Parses `FRAME:KEY[,FRAME:KEY...]`; malformed items are reported and skipped.
pub fn parse_keys(s: &str) -> Vec<(u32, Key)> {
    let mut out = Vec::new();
    for item in s.split(',').map(str::trim).filter(|i| !i.is_empty()) {
        let parsed = item
            .split_once(':')
            .and_then(|(f, k)| Some((f.trim().parse().ok()?, parse_key(k)?)));
        match parsed {
            Some(p) => out.push(p),
            None => eprintln!("softglut: SOFTGLUT_KEYS: ignoring '{item}' (want FRAME:KEY)"),
        }
    }
    out
}

/// Parses `WxH`.
fn parse_size(s: &str) -> Option<(i32, i32)> {
    let (w, h) = s.trim().split_once(['x', 'X'])?;
    let (w, h) = (w.parse().ok()?, h.parse().ok()?);
    (w > 0 && h > 0).then_some((w, h))
}

impl Config {
    /// Reads the `SOFTGLUT_*` variables.
    pub fn from_env() -> Self {
        let var = |n: &str| std::env::var(n).ok().filter(|v| !v.is_empty());
        Config {
            frames: var("SOFTGLUT_FRAMES")
                .and_then(|v| v.trim().parse().ok())
                .unwrap_or(1),
            output: var("SOFTGLUT_OUTPUT")
                .map(PathBuf::from)
                .unwrap_or_else(|| PathBuf::from(".")),
            size: var("SOFTGLUT_SIZE").and_then(|v| parse_size(&v)),
            keys: var("SOFTGLUT_KEYS")
                .map(|v| parse_keys(&v))
                .unwrap_or_default(),
            step_ms: var("SOFTGLUT_STEP_MS")
                .and_then(|v| v.trim().parse().ok())
                .filter(|&s: &i32| s >= 0)
                .unwrap_or(20),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn keys_parse() {
        assert_eq!(
            parse_keys("0:a, 3:UP,4::,5:esc,x,6:COMMA"),
            vec![
                (0, Key::Ascii(b'a')),
                (3, Key::Special(0x65)),
                (4, Key::Ascii(b':')),
                (5, Key::Ascii(27)),
                (6, Key::Ascii(b','))
            ]
        );
        assert_eq!(parse_size("320x240"), Some((320, 240)));
        assert_eq!(parse_size("0x240"), None);
    }
}
