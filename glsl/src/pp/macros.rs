//! Macro expansion: object- and function-like macros with the C rescanning rule.
//!
//! Every token carries the names of the macros whose expansion produced it (its hide
//! set); a name in its own hide set is not expanded again, which is the spec's "no
//! recursive expansion" rule and ends every self-reference. Arguments are expanded fully
//! before substitution. Exponential definitions (`#define B A A`, `#define C B B`, …)
//! are stopped by a budget on the tokens all expansions of one shader may produce.

use super::{Pp, PpError};
use crate::lex::{PpKind, PpTok};
use std::collections::VecDeque;

/// A `#define`d macro.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Macro {
    /// The parameter names of a function-like macro; `None` for an object-like one.
    pub params: Option<Vec<String>>,
    /// The replacement list.
    pub body: Vec<PpTok>,
}

impl Macro {
    /// True when `other` is the same definition (whitespace amounts aside).
    pub fn same_as(&self, other: &Macro) -> bool {
        self.params == other.params
            && self.body.len() == other.body.len()
            && self
                .body
                .iter()
                .zip(&other.body)
                .enumerate()
                .all(|(i, (a, b))| a.text == b.text && (i == 0 || a.space == b.space))
    }
}

/// The most tokens all macro expansions of one shader may produce.
pub const EXPANSION_BUDGET: usize = 1 << 20;
/// The deepest nesting of argument pre-expansion.
const MAX_ARG_DEPTH: u32 = 64;

/// A token and its hide set.
pub type HTok = (PpTok, Vec<String>);

/// Why an expansion stopped.
pub enum Stop {
    /// A function-like macro's argument list runs past the end of the tokens.
    NeedMore,
    /// An error, already reported.
    Failed,
}

impl From<PpError> for Stop {
    fn from(_: PpError) -> Stop {
        Stop::Failed
    }
}

fn punct(t: &HTok, p: &str) -> bool {
    t.0.kind == PpKind::Punct && t.0.text == p
}

impl Pp<'_> {
    /// Expands the macros of `toks` (one logical line).
    pub(super) fn expand(&mut self, toks: Vec<PpTok>) -> Result<Vec<PpTok>, Stop> {
        let input = toks.into_iter().map(|t| (t, Vec::new())).collect();
        Ok(self
            .expand_h(input, 0)?
            .into_iter()
            .map(|(t, _)| t)
            .collect())
    }

    fn charge(&mut self, n: usize, at: &PpTok) -> Result<(), Stop> {
        self.budget = self.budget.saturating_sub(n);
        if self.budget == 0 {
            self.log
                .pp_error(self.rpos(at.pos), "macro expansion exceeds the limit");
            return Err(Stop::Failed);
        }
        Ok(())
    }

    fn expand_h(&mut self, mut input: VecDeque<HTok>, depth: u32) -> Result<Vec<HTok>, Stop> {
        let mut out = Vec::new();
        while let Some((t, hide)) = input.pop_front() {
            if self.in_if && t.kind == PpKind::Ident && t.text == "defined" {
                // `defined X` and `defined ( X )`: the operand is not expanded.
                out.push((t, hide));
                let paren = input.front().is_some_and(|f| punct(f, "("));
                for _ in 0..(if paren { 3 } else { 1 }) {
                    match input.front() {
                        Some(f) if f.0.kind == PpKind::Ident || punct(f, "(") || punct(f, ")") => {
                            out.extend(input.pop_front());
                        }
                        _ => break,
                    }
                }
                continue;
            }
            if t.kind != PpKind::Ident || hide.contains(&t.text) {
                out.push((t, hide));
                continue;
            }
            if let Some(text) = self.builtin_macro(&t) {
                let mut n = t.clone();
                n.kind = PpKind::Int;
                n.text = text;
                out.push((n, hide));
                continue;
            }
            let Some(m) = self.macros.get(&t.text).cloned() else {
                out.push((t, hide));
                continue;
            };
            // `##` ending a replacement list is an error when the macro is used (one
            // starting it is passed on, and the compiler rejects it).
            if let Some(p) = m
                .body
                .last()
                .filter(|b| b.kind == PpKind::Punct && b.text == "##")
            {
                let at = self.rpos(p.pos);
                self.log
                    .pp_error(at, "'##' cannot appear at either end of a macro expansion");
                return Err(Stop::Failed);
            }
            let lead = m
                .body
                .first()
                .is_some_and(|b| b.kind == PpKind::Punct && b.text == "##");
            let mut h = hide.clone();
            h.push(t.text.clone());
            let Some(params) = &m.params else {
                self.charge(m.body.len() + 1, &t)?;
                let body = m.body.iter().map(|b| (b.clone(), h.clone())).collect();
                for (i, (mut b, bh)) in self.paste(body, lead)?.into_iter().enumerate().rev() {
                    b.pos = t.pos;
                    if i == 0 {
                        b.space = t.space;
                    }
                    input.push_front((b, bh));
                }
                continue;
            };
            if !input.front().is_some_and(|f| punct(f, "(")) {
                out.push((t, hide));
                continue;
            }
            let args = self.collect_args(&mut input)?;
            let n = if params.is_empty() && args.len() == 1 && args[0].is_empty() {
                0
            } else {
                args.len()
            };
            if n != params.len() {
                let pos = self.rpos(t.pos);
                self.log.pp_error(
                    pos,
                    format!(
                        "Error: macro {} invoked with {n} arguments (expected {})\n",
                        t.text,
                        params.len()
                    ),
                );
                return Err(Stop::Failed);
            }
            if depth >= MAX_ARG_DEPTH {
                self.log
                    .pp_error(self.rpos(t.pos), "macro arguments nest too deeply");
                return Err(Stop::Failed);
            }
            let mut expanded = Vec::with_capacity(args.len());
            for a in args {
                match self.expand_h(a.into(), depth + 1) {
                    Ok(e) => expanded.push(e),
                    Err(_) => return Err(Stop::Failed),
                }
            }
            let mut repl = Vec::new();
            for b in &m.body {
                match params.iter().position(|p| *p == b.text) {
                    Some(k) if b.kind == PpKind::Ident => {
                        for (j, (a, ah)) in expanded[k].iter().enumerate() {
                            let mut a = a.clone();
                            if j == 0 {
                                a.space = b.space;
                            }
                            let mut hs = ah.clone();
                            hs.push(t.text.clone());
                            repl.push((a, hs));
                        }
                    }
                    _ => repl.push((b.clone(), h.clone())),
                }
            }
            self.charge(repl.len() + 1, &t)?;
            for (i, (mut r, rh)) in self.paste(repl, lead)?.into_iter().enumerate().rev() {
                r.pos = t.pos;
                if i == 0 {
                    r.space = t.space;
                }
                input.push_front((r, rh));
            }
        }
        Ok(out)
    }

    /// Applies the `##` operators of a replacement list: the tokens either side are
    /// joined into one, which must scan as one token. `lead` says the macro's list
    /// starts with `##`.
    fn paste(&mut self, toks: Vec<HTok>, lead: bool) -> Result<Vec<HTok>, Stop> {
        if !toks.iter().any(|t| punct(t, "##")) {
            return Ok(toks);
        }
        let mut out: Vec<HTok> = Vec::with_capacity(toks.len());
        let mut it = toks.into_iter();
        while let Some(t) = it.next() {
            if !punct(&t, "##") {
                out.push(t);
                continue;
            }
            if out.is_empty() {
                // Nothing to paste onto: an empty argument disappears, but glcpp passes
                // on a `##` that starts the replacement list.
                if lead {
                    out.push(t);
                }
                continue;
            }
            let Some(next) = it.next() else {
                break;
            };
            let Some(prev) = out.last_mut() else {
                break;
            };
            let text = format!("{}{}", prev.0.text, next.0.text);
            let lines = crate::lex::scan(&text, &mut crate::diag::Log::default());
            match lines.as_slice() {
                [l] if l.toks.len() == 1 => {
                    prev.0.kind = l.toks[0].kind;
                    prev.0.text = text;
                }
                _ => {
                    let at = self.rpos(prev.0.pos);
                    self.log.pp_error(
                        at,
                        format!(
                            "\nPasting \"{}\" and \"{}\" does not give a valid preprocessing token.\n",
                            prev.0.text, next.0.text
                        ),
                    );
                    return Err(Stop::Failed);
                }
            }
        }
        Ok(out)
    }

    /// Takes `( a, b, … )` off the front of `input`, returning the arguments' tokens.
    fn collect_args(&mut self, input: &mut VecDeque<HTok>) -> Result<Vec<Vec<HTok>>, Stop> {
        let mut depth = 0usize;
        let mut end = None;
        for (i, t) in input.iter().enumerate().skip(1) {
            if punct(t, "(") {
                depth += 1;
            } else if punct(t, ")") {
                if depth == 0 {
                    end = Some(i);
                    break;
                }
                depth -= 1;
            }
        }
        let end = end.ok_or(Stop::NeedMore)?;
        let mut toks: Vec<HTok> = input.drain(..=end).collect();
        toks.pop();
        let mut args = vec![Vec::new()];
        let mut depth = 0usize;
        for t in toks.into_iter().skip(1) {
            if punct(&t, "(") {
                depth += 1;
            } else if punct(&t, ")") {
                depth -= 1;
            } else if punct(&t, ",") && depth == 0 {
                args.push(Vec::new());
                continue;
            }
            args.last_mut().unwrap().push(t);
        }
        Ok(args)
    }
}
