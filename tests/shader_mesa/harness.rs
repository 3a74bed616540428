//! The two sides of the shader comparison: Mesa's llvmpipe drawing a full-window quad
//! through OSMesa into a float buffer (`glsl/tests/mesa/frag_ref.c`, built here on first
//! use), and softgl's lowering run by the engine's executor over the same pixel centres.

use softgl::cpu::Isa;
use softgl::engine::exec::{self, ChunkIn, Io, Scratch};
use softgl::engine::ir::{Builder, Op};
use softgl::shader::{lower::FIRST_VARYING_PLANE, lower_fragment, Lowered};
use std::io::{BufRead, BufReader, Read, Write};
use std::path::PathBuf;
use std::process::{Command, Stdio};

/// The window's size in pixels.
pub const W: usize = 64;
/// The window's height.
pub const H: usize = 64;
/// The colour the buffer is cleared to (what a discarded pixel keeps).
pub const SENTINEL: [f32; 4] = [0.125, 0.25, 0.375, 0.5];

/// One shader drawn by both sides.
pub struct Case {
    /// Its name.
    pub name: &'static str,
    /// The built-in function family it measures.
    pub family: &'static str,
    /// The vertex shader (Mesa's side only).
    pub vs: &'static str,
    /// The fragment shader.
    pub fs: &'static str,
    /// Float uniforms by name (components in order, matrices column by column).
    pub floats: Vec<(&'static str, Vec<f32>)>,
    /// Int uniforms by name.
    pub ints: Vec<(&'static str, Vec<i32>)>,
    /// gl_MultiTexCoord0 at the corners (-1,-1), (1,-1), (1,1), (-1,1); affine in x and
    /// y with dyadic values, so that both triangles' planes are exact and equal.
    pub tex: [[f32; 4]; 4],
}

/// The pass-through vertex shader.
pub const VS: &str = "varying vec4 v;\n\
    void main() { gl_Position = gl_Vertex; v = gl_MultiTexCoord0; }\n";

fn binary() -> PathBuf {
    let out = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("frag_ref");
    let src = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("glsl/tests/mesa/frag_ref.c");
    let cc = std::env::var("CC").unwrap_or_else(|_| "cc".into());
    let status = Command::new(cc)
        .args(["-O1", "-o"])
        .arg(&out)
        .arg(&src)
        .arg("-lOSMesa")
        .status()
        .expect("run the C compiler");
    assert!(status.success(), "building frag_ref.c failed");
    out
}

/// Mesa's pixels for each case (`Err`: its info log), drawn with `caps` as
/// `GALLIUM_OVERRIDE_CPU_CAPS` when given.
pub fn mesa(cases: &[Case], caps: Option<&str>) -> Vec<Result<Vec<f32>, String>> {
    let mut cmd = Command::new(binary());
    cmd.args([W.to_string(), H.to_string()])
        .env("LP_NUM_THREADS", "1")
        .stdin(Stdio::piped())
        .stdout(Stdio::piped());
    if let Some(c) = caps {
        cmd.env("GALLIUM_OVERRIDE_CPU_CAPS", c);
    }
    let mut child = cmd.spawn().expect("start frag_ref");
    let mut input = String::new();
    let hex = |f: f32| format!("{:08x}", f.to_bits());
    for c in cases {
        input += &format!("vert {}\n{}", c.vs.len(), c.vs);
        input += &format!("frag {}\n{}", c.fs.len(), c.fs);
        for (name, v) in &c.floats {
            let (kind, n) = match v.len() {
                9 => ('m', 3),
                16 => ('m', 4),
                n => ('f', n),
            };
            let vals: Vec<String> = v.iter().map(|&x| hex(x)).collect();
            input += &format!("uni {name} {kind} {n} {}\n", vals.join(" "));
        }
        for (name, v) in &c.ints {
            let vals: Vec<String> = v.iter().map(|&x| format!("{:08x}", x as u32)).collect();
            input += &format!("uni {name} i {} {}\n", v.len(), vals.join(" "));
        }
        let t: Vec<String> = c.tex.iter().flatten().map(|&x| hex(x)).collect();
        input += &format!("tex {}\ndraw\n", t.join(" "));
    }
    let mut stdin = child.stdin.take().unwrap();
    let writer = std::thread::spawn(move || stdin.write_all(input.as_bytes()));
    let mut out = BufReader::new(child.stdout.take().unwrap());
    let mut res = Vec::new();
    for _ in cases {
        let mut head = String::new();
        out.read_line(&mut head).expect("read frag_ref");
        let mut it = head.split_whitespace();
        let ok = it.next() == Some("ok");
        let n: usize = it.next().expect("a reply").parse().unwrap();
        let mut bytes = vec![0; n];
        out.read_exact(&mut bytes).unwrap();
        res.push(if ok {
            Ok(bytes
                .chunks(4)
                .map(|b| f32::from_le_bytes([b[0], b[1], b[2], b[3]]))
                .collect())
        } else {
            Err(String::from_utf8_lossy(&bytes).into_owned())
        });
    }
    writer.join().unwrap().unwrap();
    assert!(child.wait().unwrap().success(), "frag_ref failed");
    res
}

/// The planes of a case's varyings: `v` from the corners, every other component zero.
fn planes(c: &Case, lowered: &Lowered) -> Vec<[f32; 3]> {
    // 1/w is 1 everywhere, window z 0.5 (the quad lies at z = 0).
    let mut p = vec![[1.0, 0.0, 0.0], [0.5, 0.0, 0.0]];
    assert_eq!(p.len(), FIRST_VARYING_PLANE as usize);
    for s in &lowered.varyings {
        for k in 0..s.count as usize {
            let plane = if s.name == "v" {
                let (a, b, d) = (c.tex[0][k] as f64, c.tex[1][k] as f64, c.tex[3][k] as f64);
                let dx = (b - a) / W as f64;
                let dy = (d - a) / H as f64;
                let a0 = a + 0.5 * dx + 0.5 * dy;
                for x in [dx, dy, a0] {
                    assert_eq!(
                        x as f32 as f64, x,
                        "{}: corners must give exact planes",
                        c.name
                    );
                }
                [a0 as f32, dx as f32, dy as f32]
            } else {
                [0.0; 3]
            };
            assert_eq!(p.len(), s.first as usize + k);
            p.push(plane);
        }
    }
    p
}

/// softgl's pixels for a case at level `isa` (`Err`: why it does not lower).
pub fn ours(c: &Case, isa: Isa) -> Result<Vec<f32>, String> {
    let hir = softgl_glsl::compile(&[c.fs], softgl_glsl::Stage::Fragment)
        .map_err(|log| format!("front end: {log:?}"))?;
    let lowered = lower_fragment(&hir).map_err(|e| e.0)?;
    let mut uniforms = Vec::new();
    for s in &lowered.uniforms {
        let vals: Vec<f32> = match c.floats.iter().find(|(n, _)| *n == s.name) {
            Some((_, v)) => v.clone(),
            None => match c.ints.iter().find(|(n, _)| *n == s.name) {
                Some((_, v)) => v.iter().map(|&i| f32::from_bits(i as u32)).collect(),
                None => return Err(format!("uniform {} not given", s.name)),
            },
        };
        assert_eq!(
            vals.len(),
            s.count as usize,
            "{}: uniform {}",
            c.name,
            s.name
        );
        uniforms.extend(vals);
    }
    let planes = planes(c, &lowered);
    let chunks: Vec<ChunkIn> = (0..H)
        .flat_map(|y| {
            (0..W).step_by(8).map(move |x| ChunkIn {
                idx: y * W + x,
                fx: x as f32,
                fy: y as f32,
                live: 0xFF,
                planes: 0,
            })
        })
        .collect();
    let mut out = vec![0f32; W * H * 4];
    let mut scratch = Scratch::default();
    for ch in 0..4 {
        let mut b = Builder::from_ir(lowered.ir.clone());
        let bits = b.push(Op::Bits(lowered.color[ch]));
        b.push(Op::StoreColor(0, bits));
        let ir = b.finish().map_err(|e| format!("{e:?}"))?;
        let prog = exec::compile_for(&ir, isa);
        let mut color = vec![SENTINEL[ch].to_bits().to_le_bytes(); W * H];
        let mut io = Io {
            planes: &planes,
            inputs: &[],
            color: &mut color,
            more_colors: Default::default(),
            depth: &mut [],
            uniforms: &uniforms,
            live_out: &mut [],
            sampler: None,
            stencil: &mut [],
            front: true,
            outputs: &mut [],
        };
        prog.run(&mut scratch, &mut io, &chunks, 32);
        for (i, px) in color.iter().enumerate() {
            out[i * 4 + ch] = f32::from_bits(u32::from_le_bytes(*px));
        }
    }
    Ok(out)
}

/// How two images of floats differ.
#[derive(Clone, Copy, Debug, Default)]
pub struct Diff {
    /// Channels compared.
    pub total: usize,
    /// Channels with identical bits (or both NaN).
    pub exact: usize,
    /// The largest distance in units in the last place.
    pub max_ulp: u64,
    /// The largest absolute difference.
    pub max_abs: f64,
    /// Identical channels by channel (R, G, B, A).
    pub by_channel: [usize; 4],
}

impl Diff {
    /// Adds the comparison of `a` with `b`.
    pub fn add(&mut self, a: &[f32], b: &[f32]) {
        let key = |x: f32| {
            let i = x.to_bits() as i32;
            (if i < 0 { i32::MIN.wrapping_sub(i) } else { i }) as i64
        };
        for (i, (&x, &y)) in a.iter().zip(b).enumerate() {
            self.total += 1;
            if x.to_bits() == y.to_bits() || (x.is_nan() && y.is_nan()) {
                self.exact += 1;
                self.by_channel[i % 4] += 1;
                continue;
            }
            self.max_ulp = self.max_ulp.max(key(x).abs_diff(key(y)));
            self.max_abs = self.max_abs.max((x as f64 - y as f64).abs());
        }
    }

    /// Adds another comparison's counts.
    pub fn merge(&mut self, o: &Diff) {
        self.total += o.total;
        self.exact += o.exact;
        self.max_ulp = self.max_ulp.max(o.max_ulp);
        self.max_abs = self.max_abs.max(o.max_abs);
        for (a, b) in self.by_channel.iter_mut().zip(o.by_channel) {
            *a += b;
        }
    }

    /// The exact share in percent.
    pub fn percent(&self) -> f64 {
        100.0 * self.exact as f64 / self.total.max(1) as f64
    }
}
