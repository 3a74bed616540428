//! Anisotropic filtering judged against the ground truth, not against llvmpipe.
//!
//! softgl's anisotropic filter is its own (footprint assembly of trilinear probes along the
//! major axis, `src/texture/sample.rs`), not llvmpipe's EWA of nearest texels, so a
//! byte-for-byte comparison says nothing about which is better. This test builds
//! `c_tests/tex_aniso.c` (the checkerboard ground plane at
//! `GL_TEXTURE_MAX_ANISOTROPY_EXT` 1, 2, 4, 8, 16) against softgl and against Mesa's OSMesa
//! (llvmpipe, one thread), computes the analytic ground truth in f64
//! (`bench/runner/ground_truth.rs`: the exact checkerboard averaged over each pixel's
//! square with 16×16 jittered samples through the inverse of the plane's projection), and
//! prints the mean absolute error and PSNR of both renderers for every level.
//!
//! It asserts, for every level > 1, that softgl is at least as close to the truth as
//! llvmpipe's frame of the same level from the same run in both measures: mean absolute
//! error no larger and PSNR no lower. Nothing is hard-coded from either renderer's output.
//!
//! Environment: `SOFTGL_LIB_DIR`, `CC`, `SOFTGL_ISA` and `SOFTGL_REF_CPU_CAPS` as in
//! `tests/osmesa_compare.rs`. The images and the truth are written to
//! `target/aniso_truth/`.

#[path = "../bench/runner/ground_truth.rs"]
mod ground_truth;

use std::fmt::Write as _;
use std::fs;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::SystemTime;

/// Frame size of `tex_aniso.c`.
const SIZE: usize = 256;

/// Ground-truth samples per pixel along each axis (16×16 = 256 per pixel).
const SAMPLES: usize = 16;

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// `target/<profile>`: the test executable lives in `target/<profile>/deps/`.
fn profile_dir() -> PathBuf {
    let exe = std::env::current_exe().expect("current_exe");
    exe.parent()
        .and_then(Path::parent)
        .expect("profile folder")
        .to_path_buf()
}

fn mtime(p: &Path) -> Option<SystemTime> {
    fs::metadata(p).and_then(|m| m.modified()).ok()
}

/// The folder of `libsoftgl.so`, chosen as in `tests/osmesa_compare.rs`.
fn lib_dir() -> PathBuf {
    if let Some(d) = std::env::var_os("SOFTGL_LIB_DIR") {
        return fs::canonicalize(&d).unwrap_or_else(|_| PathBuf::from(d));
    }
    let profile = profile_dir();
    let deps = profile.join("deps");
    match (
        mtime(&profile.join("libsoftgl.so")),
        mtime(&deps.join("libsoftgl.so")),
    ) {
        (Some(up), Some(dep)) if dep > up => deps,
        (None, Some(_)) => deps,
        _ => profile,
    }
}

/// Compiles and runs `c_tests/tex_aniso.c` against softgl or OSMesa; returns the output.
fn build_and_run(softgl: bool, out_dir: &Path) -> Vec<u8> {
    let side = if softgl { "softgl" } else { "osmesa" };
    let bin = out_dir.join(format!("tex_aniso.{side}"));
    let src = root().join("c_tests/tex_aniso.c");
    let cc = std::env::var("CC").unwrap_or_else(|_| "cc".into());
    let mut cmd = Command::new(&cc);
    cmd.current_dir(root()).args(["-O1", "-Wall"]);
    if softgl {
        let lib = lib_dir();
        assert!(
            lib.join("libsoftgl.so").exists(),
            "{} is missing: run cargo build --release first",
            lib.join("libsoftgl.so").display()
        );
        cmd.arg("-Werror")
            .arg(format!("-I{}", root().join("include").display()))
            .arg(&src)
            .arg("-o")
            .arg(&bin)
            .arg(format!("-L{}", lib.display()))
            .arg("-lsoftgl")
            .arg(format!("-Wl,-rpath,{}", lib.display()))
            .arg("-lm");
    } else {
        if !Path::new("/usr/include/GL/osmesa.h").exists() {
            let _ = Command::new("bash")
                .arg(root().join("scripts/ensure-deps.sh"))
                .status();
        }
        cmd.arg("-DSGL_REFERENCE_OSMESA=1")
            .arg(&src)
            .arg("-o")
            .arg(&bin)
            .args(["-Wl,--allow-shlib-undefined", "-lOSMesa", "-lm"]);
    }
    let out = cmd.output().expect("run the C compiler");
    assert!(
        out.status.success(),
        "compiling tex_aniso.c against {side} failed:\n{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let result = out_dir.join(format!("tex_aniso.{side}.out"));
    let _ = fs::remove_file(&result);
    let mut run = Command::new(&bin);
    run.arg(&result);
    if !softgl {
        run.env("GALLIUM_DRIVER", "llvmpipe")
            .env("LP_NUM_THREADS", "1");
        if let Some(caps) = softgl::cpu::reference_cpu_caps() {
            run.env("GALLIUM_OVERRIDE_CPU_CAPS", caps);
        }
    }
    let o = run.output().expect("run tex_aniso");
    assert!(
        o.status.success(),
        "tex_aniso ({side}) failed: {}\n{}",
        o.status,
        String::from_utf8_lossy(&o.stderr)
    );
    fs::read(&result).expect("tex_aniso output")
}

/// One `SGLIMG` block: name, row bytes, bottom-up flag, pixels.
struct Image {
    name: String,
    rowbytes: usize,
    y_up: bool,
    bytes: Vec<u8>,
}

/// The image blocks of a scene output (`c_tests/README.md`); other blocks are skipped.
fn images(data: &[u8]) -> Vec<Image> {
    let mut out = Vec::new();
    let mut pos = 0;
    while pos < data.len() {
        let nl = pos
            + data[pos..]
                .iter()
                .position(|&b| b == b'\n')
                .expect("header line");
        let header = String::from_utf8_lossy(&data[pos..nl]).into_owned();
        let f: Vec<&str> = header.split(' ').collect();
        let num = |i: usize| f[i].parse::<usize>().expect("header number");
        let len = match f[0] {
            "SGLIMG" => num(3) * num(6),
            _ => num(2),
        };
        let body = &data[nl + 1..nl + 1 + len];
        if f[0] == "SGLIMG" {
            assert_eq!((num(2), num(3), num(4), f[5]), (SIZE, SIZE, 4, "RGBA"));
            out.push(Image {
                name: f[1].to_owned(),
                rowbytes: num(6),
                y_up: f[7] == "up",
                bytes: body.to_vec(),
            });
        }
        pos = nl + 1 + len + 1;
    }
    out
}

/// Saves an image block as a PNG, top row first.
fn save(img: &Image, path: &Path) {
    let rgb = image::RgbImage::from_fn(SIZE as u32, SIZE as u32, |x, y| {
        let row = if img.y_up {
            SIZE - 1 - y as usize
        } else {
            y as usize
        };
        let o = row * img.rowbytes + 4 * x as usize;
        image::Rgb([img.bytes[o], img.bytes[o + 1], img.bytes[o + 2]])
    });
    let _ = rgb.save(path);
}

#[test]
fn anisotropic_filtering_against_ground_truth() {
    let out_dir = profile_dir()
        .parent()
        .map_or_else(|| root().join("target"), Path::to_path_buf)
        .join("aniso_truth");
    fs::create_dir_all(&out_dir).expect("mkdir target/aniso_truth");
    let ours = images(&build_and_run(true, &out_dir));
    let theirs = images(&build_and_run(false, &out_dir));
    assert_eq!(ours.len(), 5, "softgl wrote {} images", ours.len());
    assert_eq!(theirs.len(), 5, "OSMesa wrote {} images", theirs.len());

    let truth = ground_truth::ground_truth(SIZE, SIZE, SAMPLES);
    let _ = image::RgbImage::from_raw(SIZE as u32, SIZE as u32, truth.to_rgb())
        .map(|t| t.save(out_dir.join("truth.png")));

    let mut table = String::new();
    let _ = writeln!(
        table,
        "tex_aniso {SIZE}x{SIZE}, truth {0}x{0} samples/pixel, judged pixels {1}\n\
         | max aniso | softgl MAE | llvmpipe MAE | softgl − llvmpipe MAE | softgl RMSE | \
         llvmpipe RMSE | softgl PSNR dB | llvmpipe PSNR dB |\n\
         |---:|---:|---:|---:|---:|---:|---:|---:|",
        truth.samples,
        truth
            .error(&ours[0].bytes, ours[0].rowbytes, ours[0].y_up)
            .pixels
    );
    let mut worse = Vec::new();
    for (a, b) in ours.iter().zip(&theirs) {
        assert_eq!(a.name, b.name, "image order differs");
        save(a, &out_dir.join(format!("{}.softgl.png", a.name)));
        save(b, &out_dir.join(format!("{}.llvmpipe.png", b.name)));
        let level: u32 = a.name.trim_start_matches("aniso").parse().expect("level");
        let ea = truth.error(&a.bytes, a.rowbytes, a.y_up);
        let eb = truth.error(&b.bytes, b.rowbytes, b.y_up);
        let _ = writeln!(
            table,
            "| {level} | {:.3} | {:.3} | {:+.3} | {:.3} | {:.3} | {:.2} | {:.2} |",
            ea.mae,
            eb.mae,
            ea.mae - eb.mae,
            ea.rmse,
            eb.rmse,
            ea.psnr,
            eb.psnr,
        );
        if level > 1 && ea.mae > eb.mae {
            worse.push(format!(
                "{level}x: softgl MAE {:.3} > llvmpipe {:.3}",
                ea.mae, eb.mae
            ));
        }
        if level > 1 && ea.psnr < eb.psnr {
            worse.push(format!(
                "{level}x: softgl PSNR {:.2} dB < llvmpipe {:.2} dB",
                ea.psnr, eb.psnr
            ));
        }
    }
    println!("{table}");
    let _ = fs::write(out_dir.join("table.md"), &table);
    assert!(
        worse.is_empty(),
        "softgl's anisotropic filtering is further from the ground truth than llvmpipe's:\n{}\n{table}",
        worse.join("\n")
    );
}
