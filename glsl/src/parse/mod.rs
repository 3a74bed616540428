//! The parser: the preprocessor's tokens into the syntax tree ([`crate::ast`]).
//!
//! Hand-written recursive descent following the GLSL 3.30 grammar (the older versions'
//! grammars are subsets; which words are keywords is the lexer's business, so a 1.10
//! shader using `switch` fails there, as in Mesa). Binary operators are parsed by
//! precedence climbing ([`expr`]). Declarations and statements are in [`decl`] and
//! [`stmt`].
//!
//! GLSL's one ambiguity, whether a statement starting with a name declares or computes,
//! is settled as Mesa settles it: struct names declared so far are type names (Mesa's
//! `TYPE_IDENTIFIER`), every other name starts an expression.
//!
//! The first syntax error ends the parse, as in Mesa (its grammar has no error
//! recovery), with Mesa's message: `syntax error, unexpected X` at the offending token,
//! naming it as Mesa's bison grammar does (`NEW_IDENTIFIER`, `'}'`, `end of file`, …).
//! Nesting of statements and expressions is limited to [`MAX_DEPTH`] levels so that no
//! input can exhaust the stack; every loop consumes a token, so parsing is linear.

pub mod decl;
pub mod expr;
pub mod stmt;

use crate::diag::{Log, Pos};
use crate::lex::{mesa_name, Tok, Token, Word};
use std::collections::{HashMap, HashSet};

/// The deepest nesting of statements and expressions together.
pub const MAX_DEPTH: u32 = 256;

/// A syntax error, already written to the log.
#[derive(Debug)]
pub struct Fail;

/// What the parser's functions return.
pub type PResult<T> = Result<T, Fail>;

/// The parser's state.
pub struct Parser<'a> {
    toks: &'a [Token],
    i: usize,
    log: &'a mut Log,
    /// Struct names declared so far (Mesa's `TYPE_IDENTIFIER`s).
    types: HashSet<String>,
    /// The variables declared in each open scope (Mesa's `IDENTIFIER`s, for error
    /// messages), with the index of the first token that sees each.
    names: Vec<HashMap<String, usize>>,
    depth: u32,
    /// The shader's stage (layout identifiers depend on it).
    stage: crate::ast::Stage,
    /// The furthest token the parser has looked at (Mesa's lexer reads no further).
    furthest: std::cell::Cell<usize>,
}

static EOF: Token = Token {
    tok: Tok::Eof,
    pos: Pos {
        source: 0,
        line: 1,
        col: 1,
    },
    error: None,
};

impl<'a> Parser<'a> {
    /// A parser over `toks` (which end with [`Tok::Eof`]) of a shader of `stage`.
    pub fn new(toks: &'a [Token], stage: crate::ast::Stage, log: &'a mut Log) -> Parser<'a> {
        Parser {
            toks,
            i: 0,
            log,
            types: HashSet::new(),
            names: vec![HashMap::new()],
            depth: 0,
            stage,
            furthest: std::cell::Cell::new(0),
        }
    }

    /// The index of the furthest token looked at.
    pub fn furthest(&self) -> usize {
        self.furthest.get()
    }

    fn tok_at(&self, n: usize) -> &'a Token {
        let toks = self.toks;
        self.furthest.set(self.furthest.get().max(self.i + n));
        toks.get(self.i + n).or_else(|| toks.last()).unwrap_or(&EOF)
    }

    fn peek(&self) -> &'a Tok {
        &self.tok_at(0).tok
    }

    fn pos(&self) -> Pos {
        self.tok_at(0).pos
    }

    fn bump(&mut self) -> &'a Token {
        let t = self.tok_at(0);
        if self.i < self.toks.len() {
            self.i += 1;
        }
        t
    }

    fn is(&self, p: &str) -> bool {
        matches!(self.peek(), Tok::Punct(q) if *q == p)
    }

    fn is_at(&self, n: usize, p: &str) -> bool {
        matches!(&self.tok_at(n).tok, Tok::Punct(q) if *q == p)
    }

    fn is_word(&self, w: Word) -> bool {
        *self.peek() == Tok::Word(w)
    }

    /// Reports a syntax error at the current token.
    fn fail<T>(&mut self) -> PResult<T> {
        let t = self.peek();
        let (known, is_type) = match t {
            Tok::Ident(n) => (self.known(n), self.types.contains(n)),
            _ => (false, false),
        };
        let name = mesa_name(t, known, is_type);
        let pos = self.pos();
        self.log
            .error(pos, format!("syntax error, unexpected {name}"));
        Err(Fail)
    }

    fn expect(&mut self, p: &str) -> PResult<Pos> {
        if self.is(p) {
            Ok(self.bump().pos)
        } else {
            self.fail()
        }
    }

    /// Takes a name (any identifier, struct names included).
    fn ident(&mut self) -> PResult<(String, Pos)> {
        match self.peek() {
            Tok::Ident(n) => {
                let pos = self.bump().pos;
                Ok((n.clone(), pos))
            }
            _ => self.fail(),
        }
    }

    /// Whether `name` is a declared variable or function at the current token (Mesa's
    /// `IDENTIFIER` rather than `NEW_IDENTIFIER`).
    fn known(&self, name: &str) -> bool {
        self.names
            .iter()
            .any(|m| m.get(name).is_some_and(|&k| k <= self.i))
    }

    /// Records a declared variable. Mesa's grammar enters it into the symbol table when
    /// it reduces the declaration, after the lexer has read the next token, so names
    /// are known from the token after that one. (Built-ins are not in the table while
    /// Mesa parses, so `gl_Position` is a `NEW_IDENTIFIER` to its syntax errors.)
    fn declare(&mut self, name: &str) {
        let from = self.i + 1;
        if let Some(scope) = self.names.last_mut() {
            scope.entry(name.to_string()).or_insert(from);
        }
    }

    /// Records a function's name (file scope, like Mesa's function symbols).
    fn declare_function(&mut self, name: &str) {
        let from = self.i + 1;
        if let Some(scope) = self.names.first_mut() {
            scope.entry(name.to_string()).or_insert(from);
        }
    }

    /// Opens a scope for declared names (a compound statement or a `for`).
    fn push_scope(&mut self) {
        self.names.push(HashMap::new());
    }

    /// Closes the innermost scope.
    fn pop_scope(&mut self) {
        if self.names.len() > 1 {
            self.names.pop();
        }
    }

    fn enter(&mut self) -> PResult<()> {
        self.depth += 1;
        if self.depth > MAX_DEPTH {
            let pos = self.pos();
            self.log.error(
                pos,
                format!("syntax error, nesting deeper than {MAX_DEPTH} levels"),
            );
            return Err(Fail);
        }
        Ok(())
    }

    fn leave(&mut self) {
        self.depth -= 1;
    }

    /// Parses the whole translation unit.
    pub fn translation_unit(&mut self) -> PResult<Vec<crate::ast::External>> {
        let mut items = Vec::new();
        while *self.peek() != Tok::Eof {
            if self.is(";") {
                // An empty declaration at file scope (Mesa accepts it).
                self.bump();
                continue;
            }
            items.push(self.external()?);
        }
        Ok(items)
    }
}
