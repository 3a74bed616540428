//! Declarations: qualifiers, type specifiers, structs, variables, interface blocks,
//! `precision` statements, function prototypes and definitions.

use super::{PResult, Parser};
use crate::ast::Stage;
use crate::ast::{
    ArraySize, Block, Decl, Declarator, External, FullType, FunctionDef, Interp, LayoutId, Member,
    Param, Precision, Prototype, Qualifier, Storage, StructSpec, TypeName, TypeSpec,
};
use crate::diag::Pos;
use crate::lex::{Tok, Word};

fn qualifier_word(w: Word) -> Option<Qualifier> {
    use Qualifier as Q;
    Some(match w {
        Word::Const => Q::Storage(Storage::Const),
        Word::In => Q::Storage(Storage::In),
        Word::Out => Q::Storage(Storage::Out),
        Word::Inout => Q::Storage(Storage::Inout),
        Word::Attribute => Q::Storage(Storage::Attribute),
        Word::Uniform => Q::Storage(Storage::Uniform),
        Word::Varying => Q::Storage(Storage::Varying),
        Word::Centroid => Q::Storage(Storage::Centroid),
        Word::Flat => Q::Interp(Interp::Flat),
        Word::Smooth => Q::Interp(Interp::Smooth),
        Word::Noperspective => Q::Interp(Interp::Noperspective),
        Word::Invariant => Q::Invariant,
        Word::Lowp => Q::Precision(Precision::Lowp),
        Word::Mediump => Q::Precision(Precision::Mediump),
        Word::Highp => Q::Precision(Precision::Highp),
        _ => return None,
    })
}

impl Parser<'_> {
    /// True when the current token starts a type specifier.
    pub(super) fn at_type(&self, n: usize) -> bool {
        match &self.tok_at(n).tok {
            Tok::Type(_) | Tok::Word(Word::Void | Word::Struct) => true,
            Tok::Ident(name) => self.types.contains(name),
            _ => false,
        }
    }

    /// True when the current token starts a qualifier.
    pub(super) fn at_qualifier(&self) -> bool {
        matches!(self.peek(), Tok::Word(w) if *w == Word::Layout || qualifier_word(*w).is_some())
    }

    /// Qualifiers, in written order.
    pub fn qualifiers(&mut self) -> PResult<Vec<Qualifier>> {
        let mut qs = Vec::new();
        while let Tok::Word(w) = self.peek() {
            if *w == Word::Layout {
                self.bump();
                qs.push(Qualifier::Layout(self.layout()?));
            } else if let Some(q) = qualifier_word(*w) {
                self.bump();
                qs.push(q);
            } else {
                break;
            }
        }
        Ok(qs)
    }

    fn layout(&mut self) -> PResult<Vec<LayoutId>> {
        self.expect("(")?;
        let mut ids = Vec::new();
        loop {
            let pos = self.pos();
            let name = match self.peek() {
                Tok::Ident(n) => n.clone(),
                Tok::Word(w @ (Word::RowMajor | Word::Packed)) => w.text().to_string(),
                _ => return self.fail(),
            };
            self.bump();
            let value = if self.is("=") {
                self.bump();
                Some(self.conditional()?)
            } else {
                None
            };
            if !self.layout_id_known(&name, value.is_some()) {
                // Mesa's grammar action reports it and stops the parse (`YYERROR`
                // without error recovery), before any syntax error after it.
                self.log
                    .error(pos, format!("unrecognized layout identifier `{name}'"));
                return Err(super::Fail);
            }
            ids.push(LayoutId { name, value, pos });
            if !self.is(",") {
                break;
            }
            self.bump();
        }
        self.expect(")")?;
        Ok(ids)
    }

    /// Whether Mesa's grammar knows a layout identifier (with `= value` or alone) for
    /// this stage; it compares them without regard to case.
    fn layout_id_known(&self, name: &str, valued: bool) -> bool {
        let n = name.to_ascii_lowercase();
        let n = n.as_str();
        let stage = self.stage;
        if valued {
            return n == "location"
                || (stage == Stage::Fragment && n == "index")
                || (stage == Stage::Geometry && matches!(n, "max_vertices" | "invocations"));
        }
        matches!(
            n,
            "shared" | "packed" | "std140" | "row_major" | "column_major"
        ) || (stage == Stage::Fragment && matches!(n, "origin_upper_left" | "pixel_center_integer"))
            || (stage == Stage::Geometry
                && matches!(
                    n,
                    "points"
                        | "lines"
                        | "lines_adjacency"
                        | "triangles"
                        | "triangles_adjacency"
                        | "line_strip"
                        | "triangle_strip"
                ))
    }

    /// Array dimensions: `[]` or `[size]`, repeated.
    pub fn array_sizes(&mut self) -> PResult<Vec<ArraySize>> {
        let mut dims = Vec::new();
        while self.is("[") {
            self.bump();
            if self.is("]") {
                dims.push(None);
            } else {
                dims.push(Some(self.conditional()?));
            }
            self.expect("]")?;
        }
        Ok(dims)
    }

    /// A type specifier: a basic type, `void`, a struct name or a struct, and array
    /// dimensions.
    pub fn type_spec(&mut self) -> PResult<TypeSpec> {
        let pos = self.pos();
        let name = match self.peek() {
            Tok::Type(n) => {
                self.bump();
                TypeName::Named(n.clone())
            }
            Tok::Word(Word::Void) => {
                self.bump();
                TypeName::Named("void".into())
            }
            Tok::Ident(n) if self.types.contains(n) => {
                self.bump();
                TypeName::Named(n.clone())
            }
            Tok::Word(Word::Struct) => TypeName::Struct(self.struct_spec()?),
            _ => return self.fail(),
        };
        let array = self.array_sizes()?;
        Ok(TypeSpec { name, array, pos })
    }

    fn struct_spec(&mut self) -> PResult<StructSpec> {
        let pos = self.bump().pos;
        let name = match self.peek() {
            Tok::Ident(_) => Some(self.ident()?.0),
            _ => None,
        };
        self.expect("{")?;
        self.enter()?;
        let members = self.members();
        self.leave();
        let members = members?;
        if let Some(n) = &name {
            self.types.insert(n.clone());
        }
        Ok(StructSpec { name, members, pos })
    }

    /// Member declarations up to and including `}` (at least one).
    fn members(&mut self) -> PResult<Vec<Member>> {
        let mut members = Vec::new();
        loop {
            let qualifiers = self.qualifiers()?;
            let spec = self.type_spec()?;
            let mut names = Vec::new();
            loop {
                let (name, pos) = self.ident()?;
                let array = self.array_sizes()?;
                names.push(Declarator {
                    name,
                    array,
                    init: None,
                    pos,
                });
                if !self.is(",") {
                    break;
                }
                self.bump();
            }
            self.expect(";")?;
            members.push(Member {
                ty: FullType { qualifiers, spec },
                names,
            });
            if self.is("}") {
                self.bump();
                return Ok(members);
            }
        }
    }

    /// An external declaration: a declaration or a function definition.
    pub fn external(&mut self) -> PResult<External> {
        self.declaration(true)
    }

    /// A declaration; at file scope (`top`) a prototype may be followed by a body.
    pub fn declaration(&mut self, top: bool) -> PResult<External> {
        let start = self.pos();
        if self.is_word(Word::Precision) {
            self.bump();
            let precision = match self.peek() {
                Tok::Word(Word::Lowp) => Precision::Lowp,
                Tok::Word(Word::Mediump) => Precision::Mediump,
                Tok::Word(Word::Highp) => Precision::Highp,
                _ => return self.fail(),
            };
            self.bump();
            let ty = self.type_spec()?;
            self.expect(";")?;
            return Ok(External::Decl(Decl::Precision {
                precision,
                ty,
                pos: start,
            }));
        }
        let qualifiers = self.qualifiers()?;
        // `layout(...) uniform;` and interface blocks take layouts and one of `in`,
        // `out`, `uniform`, as Mesa's `layout_defaults` and `interface_qualifier`.
        let interface = matches!(
            qualifiers.last(),
            Some(Qualifier::Storage(
                Storage::In | Storage::Out | Storage::Uniform
            ))
        ) && qualifiers[..qualifiers.len() - 1]
            .iter()
            .all(|q| matches!(q, Qualifier::Layout(_)));
        // Layout defaults are file-scope declarations only.
        if interface && top && qualifiers.len() > 1 && self.is(";") {
            self.bump();
            return Ok(External::Decl(Decl::Default {
                qualifiers,
                pos: start,
            }));
        }
        if let Tok::Ident(n) = self.peek() {
            if !self.types.contains(n) && !self.known(n) {
                if qualifiers == [Qualifier::Invariant] {
                    return self.invariant_list();
                }
                if interface {
                    return self.block(qualifiers);
                }
            }
        }
        let spec = self.type_spec()?;
        let ty = FullType { qualifiers, spec };
        if self.is(";") {
            self.bump();
            return Ok(External::Decl(Decl::Vars { ty, vars: vec![] }));
        }
        if self.is(",") {
            // Mesa's grammar lets a declarator list start with a type alone
            // (`vec3 , a;`); its checker then warns of the empty declaration.
            let mut vars = Vec::new();
            while self.is(",") {
                self.bump();
                let (name, pos) = self.ident()?;
                vars.push(self.declarator_rest(name, pos)?);
            }
            self.expect(";")?;
            return Ok(External::Decl(Decl::Vars { ty, vars }));
        }
        let (name, pos) = self.ident()?;
        if self.is("(") {
            let params = self.params()?;
            self.declare_function(&name);
            let proto = Prototype {
                ret: ty,
                name,
                params,
                pos,
            };
            if top && self.is("{") {
                self.push_scope();
                for p in &proto.params {
                    if let Some(n) = &p.name {
                        self.declare(n);
                    }
                }
                self.bump();
                let body = self.statements_until_brace();
                self.pop_scope();
                let body = body?;
                return Ok(External::Function(FunctionDef { proto, body }));
            }
            self.expect(";")?;
            return Ok(External::Decl(Decl::Prototype(proto)));
        }
        let mut vars = vec![self.declarator_rest(name, pos)?];
        while self.is(",") {
            self.bump();
            let (name, pos) = self.ident()?;
            vars.push(self.declarator_rest(name, pos)?);
        }
        self.expect(";")?;
        Ok(External::Decl(Decl::Vars { ty, vars }))
    }

    fn declarator_rest(&mut self, name: String, pos: Pos) -> PResult<Declarator> {
        let array = self.array_sizes()?;
        let init = if self.is("=") {
            self.bump();
            Some(self.initializer()?)
        } else {
            None
        };
        self.declare(&name);
        Ok(Declarator {
            name,
            array,
            init,
            pos,
        })
    }

    /// An initializer: an assignment expression or a brace list (`{ a, { b }, }`,
    /// which Mesa's grammar parses in every version and its checker rejects before
    /// 4.20).
    fn initializer(&mut self) -> PResult<crate::ast::Expr> {
        if !self.is("{") {
            return self.assignment();
        }
        let pos = self.bump().pos;
        self.enter()?;
        let mut items = Vec::new();
        let r = loop {
            match self.initializer() {
                Ok(e) => items.push(e),
                Err(f) => break Err(f),
            }
            if self.is(",") {
                self.bump();
                if !self.is("}") {
                    continue;
                }
            }
            break self.expect("}").map(|_| ());
        };
        self.leave();
        r?;
        Ok(crate::ast::Expr {
            kind: crate::ast::ExprKind::InitList(items),
            pos,
        })
    }

    fn invariant_list(&mut self) -> PResult<External> {
        let mut names = vec![self.ident()?];
        while self.is(",") {
            self.bump();
            names.push(self.ident()?);
        }
        self.expect(";")?;
        Ok(External::Decl(Decl::Invariant { names }))
    }

    fn block(&mut self, qualifiers: Vec<Qualifier>) -> PResult<External> {
        let (name, pos) = self.ident()?;
        self.expect("{")?;
        let members = self.members()?;
        let instance = match self.peek() {
            Tok::Ident(_) => {
                let (n, _) = self.ident()?;
                Some((n, self.array_sizes()?))
            }
            _ => None,
        };
        self.expect(";")?;
        Ok(External::Decl(Decl::Block(Block {
            qualifiers,
            name,
            members,
            instance,
            pos,
        })))
    }

    /// `( params )`; `()` and `(void)` give none.
    fn params(&mut self) -> PResult<Vec<Param>> {
        self.expect("(")?;
        let mut params = Vec::new();
        if self.is_word(Word::Void) && self.is_at(1, ")") {
            self.bump();
        } else if !self.is(")") {
            loop {
                let pos = self.pos();
                let mut qualifiers = Vec::new();
                while let Tok::Word(
                    w @ (Word::Const
                    | Word::In
                    | Word::Out
                    | Word::Inout
                    | Word::Lowp
                    | Word::Mediump
                    | Word::Highp),
                ) = self.peek()
                {
                    qualifiers.extend(qualifier_word(*w));
                    self.bump();
                }
                let spec = self.type_spec()?;
                let (name, array) = match self.peek() {
                    Tok::Ident(_) => {
                        let (n, _) = self.ident()?;
                        (Some(n), self.array_sizes()?)
                    }
                    _ => (None, vec![]),
                };
                params.push(Param {
                    ty: FullType { qualifiers, spec },
                    name,
                    array,
                    pos,
                });
                if !self.is(",") {
                    break;
                }
                self.bump();
            }
        }
        self.expect(")")?;
        Ok(params)
    }
}
