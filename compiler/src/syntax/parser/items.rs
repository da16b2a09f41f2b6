//! The module level: imports, attributes, doc comments and the items `fn`, `struct`, `const`
//! (scenes are in [`super::scene`]).
//!
//! `module = import* item*`. An import after an item is reported (`E0308`) and still recorded, so
//! name resolution sees it. Junk at the top level is reported once and skipped to the next item
//! keyword or `@`.
//!
//! Doc comments: the `///` lines before an item's first token (its first attribute, or its keyword)
//! and before its keyword (between attributes and keyword) are joined; a struct field's are the
//! lines before its name.
//!
//! Invariants:
//! - An item's span runs from its first attribute (or keyword) to its last token.
//! - Unknown attribute names are reported here (`E0203`, with the closest known name as help);
//!   whether a known attribute fits the item is for semantic analysis (`E0602`).

use super::{Parser, Restrict, ITEM_START};
use crate::syntax::ast::{
    AttrArg, Attribute, ConstDecl, FieldDecl, FnDecl, Import, Item, ItemKind, Param, StructDecl,
};
use crate::syntax::error::{Expected, Hint, Place, SyntaxError, KNOWN_ATTRIBUTES};
use crate::syntax::lexer;
use crate::syntax::token::{TokenKind, TokenSet};

/// Tokens that may follow a whole item-level construct; top-level recovery stops at them.
const TOP_RECOVERY: TokenSet = ITEM_START.union(TokenSet::new(&[TokenKind::Let, TokenKind::Var]));

impl Parser<'_> {
    /// The whole file.
    pub(super) fn module(&mut self) {
        let mut first_item = None;
        loop {
            self.too_deep_reported = false;
            let lo = self.span();
            let before = self.pos;
            match self.kind() {
                TokenKind::Eof => break,
                TokenKind::Import => {
                    let Some(import) = self.import() else {
                        continue;
                    };
                    if let Some(first_item) = first_item {
                        self.report(SyntaxError::ImportAfterItem {
                            span: import.span,
                            first_item,
                        });
                    }
                    self.m.imports.push(import);
                }
                TokenKind::Fn
                | TokenKind::Struct
                | TokenKind::Const
                | TokenKind::Scene
                | TokenKind::At => {
                    let item = self.item();
                    first_item.get_or_insert(self.first_line(item.span));
                    self.m.items.push(item);
                }
                k @ (TokenKind::Let | TokenKind::Var) => {
                    self.report(SyntaxError::MisplacedItem {
                        keyword: k,
                        place: Place::TopLevel,
                        span: lo,
                    });
                    self.bump();
                    self.recover(TokenSet::new(&[TokenKind::Semi]).union(TOP_RECOVERY));
                    self.eat(TokenKind::Semi);
                    self.push_error_item(lo);
                }
                TokenKind::Semi => {
                    self.expected(Expected::Item, Some(Hint::RemoveSemicolon));
                    self.bump();
                }
                _ => {
                    self.expected(Expected::Item, None);
                    self.bump();
                    self.recover(TOP_RECOVERY);
                    self.push_error_item(lo);
                }
            }
            if self.pos == before {
                self.bump();
                if self.pos == before {
                    break;
                }
            }
        }
    }

    fn push_error_item(&mut self, lo: crate::source::Span) {
        let span = self.since(lo);
        self.m.items.push(Item {
            attrs: Vec::new(),
            doc: None,
            kind: ItemKind::Error,
            span,
        });
    }

    /// `import "path";`, or `None` without a path (reported; nothing for name resolution to load).
    pub(super) fn import(&mut self) -> Option<Import> {
        let lo = self.bump();
        if !self.at(TokenKind::Str) {
            self.expected(Expected::Path, None);
            self.recover(TokenSet::new(&[TokenKind::Semi]).union(TOP_RECOVERY));
            self.eat(TokenKind::Semi);
            return None;
        }
        let path_span = self.bump();
        let path = lexer::unescape(self.text(path_span));
        self.expect_semi();
        Some(Import {
            path,
            path_span,
            span: self.since(lo),
        })
    }

    /// An item with its doc comment and attributes.
    pub(super) fn item(&mut self) -> Item {
        let lo = self.span();
        let mut doc = self.doc_at(self.pos);
        let mut attrs = Vec::new();
        while self.at(TokenKind::At) {
            attrs.extend(self.attribute());
        }
        if !attrs.is_empty() {
            if let Some(more) = self.doc_at(self.pos) {
                doc = Some(match doc {
                    Some(d) => format!("{d}\n{more}"),
                    None => more,
                });
            }
        }
        let kind = match self.kind() {
            TokenKind::Fn => self.fn_decl(),
            TokenKind::Struct => self.struct_decl(),
            TokenKind::Const => self.const_decl(),
            TokenKind::Scene => self.scene_decl(),
            _ => {
                self.expected(
                    Expected::OneOf(&[
                        TokenKind::Fn,
                        TokenKind::Struct,
                        TokenKind::Const,
                        TokenKind::Scene,
                    ]),
                    None,
                );
                ItemKind::Error
            }
        };
        Item {
            attrs,
            doc,
            kind,
            span: self.since(lo),
        }
    }

    /// `@name` or `@name(args)`, at the `@`.
    fn attribute(&mut self) -> Option<Attribute> {
        let lo = self.bump();
        let name = self.expect_ident()?;
        if !KNOWN_ATTRIBUTES.contains(&name.name.as_str()) {
            let suggestion =
                crate::diag::suggest::closest(&name.name, KNOWN_ATTRIBUTES.iter().copied());
            self.report(SyntaxError::UnknownAttribute {
                name: name.name.clone(),
                suggestion,
                span: name.span,
            });
        }
        let mut args = Vec::new();
        if self.at(TokenKind::LParen) {
            let open = self.bump();
            let stop = TokenSet::new(&[TokenKind::Semi, TokenKind::LBrace, TokenKind::RBrace])
                .union(ITEM_START);
            args = self.list(TokenKind::RParen, stop, None, |p| {
                let lo = p.span();
                let name = if p.at(TokenKind::Ident) && p.nth(1) == TokenKind::Eq {
                    let name = p.ident();
                    p.bump();
                    Some(name)
                } else {
                    None
                };
                let value = p.expr(Restrict::NONE);
                Some(AttrArg {
                    name,
                    value,
                    span: p.since(lo),
                })
            });
            self.expect_close(TokenKind::RParen, open);
        }
        Some(Attribute {
            name,
            args,
            span: self.since(lo),
        })
    }

    /// `fn name(params) (-> T)? { … }`
    fn fn_decl(&mut self) -> ItemKind {
        self.bump();
        let name = self.expect_ident();
        let mut params = Vec::new();
        if self.at(TokenKind::LParen) {
            let open = self.bump();
            let stop = TokenSet::new(&[
                TokenKind::LBrace,
                TokenKind::RBrace,
                TokenKind::Semi,
                TokenKind::Arrow,
            ]);
            params = self.list(
                TokenKind::RParen,
                stop,
                Some(TokenKind::Ident),
                Parser::param,
            );
            self.expect_close(TokenKind::RParen, open);
        } else {
            self.expected(Expected::Token(TokenKind::LParen), None);
            self.recover(TokenSet::new(&[
                TokenKind::LBrace,
                TokenKind::Arrow,
                TokenKind::Semi,
            ]));
        }
        let ret = self.eat(TokenKind::Arrow).map(|_| self.ty());
        let body = self.block();
        match name {
            Some(name) => ItemKind::Fn(FnDecl {
                name,
                params,
                ret,
                body,
            }),
            None => ItemKind::Error,
        }
    }

    /// `name: T`
    fn param(&mut self) -> Option<Param> {
        let name = self.expect_ident()?;
        if self.eat(TokenKind::Colon).is_none() {
            let hint = Hint::ParamNeedsType {
                name: name.name.clone(),
            };
            self.expected(Expected::Token(TokenKind::Colon), Some(hint));
            if !matches!(self.kind(), TokenKind::Comma | TokenKind::RParen) {
                return None;
            }
            let span = name.span;
            let ty = self.m.types.alloc(crate::syntax::ast::TypeExpr {
                kind: crate::syntax::ast::TypeExprKind::Error,
                span: span.end(),
            });
            return Some(Param { name, ty, span });
        }
        let ty = self.ty();
        let span = self.since(name.span);
        Some(Param { name, ty, span })
    }

    /// `struct Name { fields }`
    fn struct_decl(&mut self) -> ItemKind {
        self.bump();
        let name = self.expect_ident();
        let mut fields = Vec::new();
        if self.at(TokenKind::LBrace) {
            let open = self.bump();
            let stop = TokenSet::new(&[TokenKind::Semi]);
            fields = self.list(
                TokenKind::RBrace,
                stop,
                Some(TokenKind::Ident),
                Parser::field_decl,
            );
            self.expect_close(TokenKind::RBrace, open);
        } else {
            self.expected(Expected::Token(TokenKind::LBrace), None);
        }
        match name {
            Some(name) => ItemKind::Struct(StructDecl { name, fields }),
            None => ItemKind::Error,
        }
    }

    /// `name: T (= default)?`, with its doc comment.
    fn field_decl(&mut self) -> Option<FieldDecl> {
        if ITEM_START.contains(self.kind()) {
            self.report(SyntaxError::MisplacedItem {
                keyword: self.kind(),
                place: Place::Struct,
                span: self.span(),
            });
            self.nested_item();
            self.last_error_pos = self.pos;
            return None;
        }
        let doc = self.doc_at(self.pos);
        let name = self.expect_ident()?;
        if !self.expect(TokenKind::Colon) {
            return None;
        }
        let ty = self.ty();
        let default = self.eat(TokenKind::Eq).map(|_| self.expr(Restrict::NONE));
        Some(FieldDecl {
            doc,
            span: self.since(name.span),
            name,
            ty,
            default,
        })
    }

    /// `const NAME (: T)? = value;`
    fn const_decl(&mut self) -> ItemKind {
        self.bump();
        let Some(name) = self.expect_ident() else {
            self.recover(TokenSet::new(&[TokenKind::Semi]).union(TOP_RECOVERY));
            self.eat(TokenKind::Semi);
            return ItemKind::Error;
        };
        let ty = self.eat(TokenKind::Colon).map(|_| self.ty());
        let value = if self.eat(TokenKind::Eq).is_some() {
            self.expr(Restrict::NONE)
        } else {
            self.expected(Expected::Token(TokenKind::Eq), None);
            self.recover(TokenSet::new(&[TokenKind::Semi]).union(TOP_RECOVERY));
            self.error_expr(self.prev_end())
        };
        self.expect_semi();
        ItemKind::Const(ConstDecl { name, ty, value })
    }
}
