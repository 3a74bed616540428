//! glBlitFramebuffer on the state: checks the read and draw buffers, gathers the source
//! (resolving a multisample one) and runs [`crate::pixels::blit`]'s clipped copy into
//! every destination sample.

use super::super::fbo::SAMPLES;
use super::super::{Context, GlError, GlResult};
use crate::pixels::blit::{clip_axis, resolve_samples, BlitMask, Job};
use crate::pixels::blit_srgb::SrgbSides;

/// glBlitFramebuffer after argument checks: `src`/`dst` are (x0, y0, x1, y1) in GL window
/// coordinates (y up).
pub fn blit(
    ctx: &mut Context,
    src: [i32; 4],
    dst: [i32; 4],
    mask: BlitMask,
    linear: bool,
) -> GlResult<()> {
    ctx.check_draw_framebuffer()?;
    ctx.check_read_framebuffer()?;
    // Mesa's blit_framebuffer: with a multisample buffer on either side the rectangles
    // must have the same size (offsets and mirroring are allowed).
    let (read_ms, draw_ms) = (ctx.read_samples() > 0, ctx.draw_samples() > 0);
    if (read_ms || draw_ms)
        && ((src[2] - src[0]).abs() != (dst[2] - dst[0]).abs()
            || (src[3] - src[1]).abs() != (dst[3] - dst[1]).abs())
    {
        return Err(GlError::InvalidOperation);
    }
    // Every sample plane of a multisample source (a resolve averages them).
    let mut planes = Vec::new();
    let fma = crate::geometry::cpu_has_fma();
    let caps = &ctx.state.caps;
    let dst_srgb = ctx.fb.as_ref().is_some_and(|f| f.srgb);
    let mut sides = SrgbSides {
        src: false,
        dst: crate::plan::srgb_store(caps, dst_srgb),
    };
    let mut sfb = if read_ms && !draw_ms {
        // A resolve reads the source planes where they are (nothing copied).
        let wide_dst = ctx.fb.as_ref().is_some_and(|f| f.wide.is_some());
        let on = crate::plan::srgb_store(caps, true);
        let scratch = ctx.fbo.resolve_scratch.take();
        let resolved = ctx.with_read_planes(|planes| {
            (planes.len() == SAMPLES).then(|| {
                let sides = SrgbSides {
                    src: on && planes[0].srgb,
                    ..sides
                };
                resolve_samples(planes, sides, wide_dst, fma, mask, scratch)
            })
        });
        let Some(Some(resolved)) = resolved else {
            return Ok(());
        };
        // the resolve has converted the colours: the copy that follows copies
        sides = SrgbSides::default();
        resolved
    } else if read_ms {
        planes = ctx.read_planes().unwrap_or_default();
        for p in &mut planes {
            p.resolve();
        }
        if planes.len() != SAMPLES {
            return Ok(());
        }
        sides.src = crate::plan::srgb_store(&ctx.state.caps, planes[0].srgb);
        let wide_dst = ctx.fb.as_ref().is_some_and(|f| f.wide.is_some());
        let scratch = ctx.fbo.resolve_scratch.take();
        let resolved = resolve_samples(&planes, sides, wide_dst, fma, mask, scratch);
        // the resolve has converted the colours: the copy that follows copies
        sides = SrgbSides::default();
        resolved
    } else {
        // Reading and drawing one buffer: read a snapshot.
        match ctx.read_framebuffer_copy() {
            Some(f) => f,
            None => match ctx.fb.as_ref() {
                Some(f) => f.clone(),
                None => return Ok(()),
            },
        }
    };
    sfb.resolve();
    if !read_ms {
        sides.src = crate::plan::srgb_store(&ctx.state.caps, sfb.srgb);
    }
    let Some(dfb) = ctx.fb.as_ref() else {
        return Ok(());
    };
    if mask.depth && (sfb.depth.is_empty() || dfb.depth.is_empty()) {
        return Ok(());
    }
    if mask.depth && sfb.depth_format != dfb.depth_format {
        return Err(GlError::InvalidOperation);
    }
    // The draw buffer ∩ scissor in GL coordinates (Mesa's _Xmin.._Ymax).
    let Some(region) = ctx.draw_region() else {
        return Ok(());
    };
    let dh = dfb.height as i32;
    let (sw, sh) = (sfb.width as i32, sfb.height as i32);
    let gl_rows = |r: [i64; 4]| {
        if dfb.y_flip {
            (dh - r[3] as i32, dh - r[1] as i32)
        } else {
            (r[1] as i32, r[3] as i32)
        }
    };
    let (ylo, yhi) = gl_rows(region);
    let (mut cs, mut cd) = ([src[0], src[2]], [dst[0], dst[2]]);
    let (mut ct, mut ce) = ([src[1], src[3]], [dst[1], dst[3]]);
    if !clip_axis(&mut cs, &mut cd, region[0] as i32, region[2] as i32, sw)
        || !clip_axis(&mut ct, &mut ce, ylo, yhi, sh)
    {
        return Ok(());
    }
    // The clipped destination, as a scissor in memory rows.
    let flip = |y: i32, h: i32, f: bool| if f { h - y } else { y };
    let (sy0, sy1) = (flip(ce[0], dh, dfb.y_flip), flip(ce[1], dh, dfb.y_flip));
    let scissor = [
        cd[0].min(cd[1]) as i64,
        sy0.min(sy1) as i64,
        cd[0].max(cd[1]) as i64,
        sy0.max(sy1) as i64,
    ];
    // The unclipped rectangles in memory rows, right side up, destination positive.
    let (mut dy0, mut dy1) = (flip(dst[1], dh, dfb.y_flip), flip(dst[3], dh, dfb.y_flip));
    let (mut sy0, mut sy1) = (flip(src[1], sh, sfb.y_flip), flip(src[3], sh, sfb.y_flip));
    if sy0 > sy1 && dy0 > dy1 {
        (sy0, sy1, dy0, dy1) = (sy1, sy0, dy1, dy0);
    }
    let (bx, sx, bw, swid) = if dst[0] < dst[2] {
        (dst[0], src[0], dst[2] - dst[0], src[2] - src[0])
    } else {
        (dst[2], src[2], dst[0] - dst[2], src[0] - src[2])
    };
    let (by, sy, bh, shgt) = if dy0 < dy1 {
        (dy0, sy0, dy1 - dy0, sy1 - sy0)
    } else {
        (dy1, sy1, dy0 - dy1, sy0 - sy1)
    };
    let job = Job {
        dst: [bx, by, bw, bh],
        src: [sx, sy, swid, shgt],
        scissor,
        normalized: !sfb.y_flip,
        linear: linear && (bw != swid.abs() || bh != shgt.abs()),
        fma,
        srgb: sides,
    };
    // Into a multisample object: sample for sample from a multisample source, else every
    // sample gets the source's value.
    ctx.for_each_sample(|c, s| {
        let src = if draw_ms && read_ms { &planes[s] } else { &sfb };
        if let Some(fb) = c.fb.as_mut() {
            fb.resolve();
            fb.uniform_color = None;
            job.run(src, fb, mask);
        }
    });
    if read_ms {
        // kept for the next resolve (a frame's resolve then touches no fresh page)
        ctx.fbo.resolve_scratch = Some(sfb);
    }
    ctx.dirty = true;
    ctx.fbo.drawn = true;
    Ok(())
}
