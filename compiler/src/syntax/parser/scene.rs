//! Scenes: `scene name { entry* }` (spec/scenes.md).
//!
//! An entry starts with `let` or one of the contextual keywords `settings camera background object
//! light model`, which are ordinary identifiers everywhere else. Entries other than `let` have no
//! terminator: an entry's expression ends where the next token cannot continue it (the next entry's
//! keyword is an identifier, which cannot follow an expression).
//!
//! Ambiguities resolved here:
//! - `light a B { … }` names the light `a`; `light B { … }` is unnamed: a light is named exactly when
//!   two identifiers follow `light`.
//! - `object a { … }` is named, `object { … }` is not.
//! - `animate a.b keys { … }` / `animate a spin(…)`: the target is one or two names; the motion is
//!   a word followed by `(` (a motion over time) or by an optional interpolation word and `{` (keys,
//!   `time: value` pairs separated by commas).
//!
//! Recovery: an unknown word at the start of an entry is `E0701` (with the closest entry keyword as
//! help); other junk is `E0201`. Either way the parser skips to the next entry keyword, `let` or `}`
//! outside any group.

use super::{Parser, Restrict, ITEM_START};
use crate::syntax::ast::{AnimMotion, ItemKind, Keyframe, SceneDecl, SceneEntry, SceneEntryKind};
use crate::syntax::error::{Expected, Hint, Place, SyntaxError, SCENE_ENTRIES};
use crate::syntax::lexer;
use crate::syntax::token::TokenKind;
use crate::syntax::token::TokenSet;

impl Parser<'_> {
    /// `scene name { entries }`
    pub(super) fn scene_decl(&mut self) -> ItemKind {
        self.bump();
        let name = self.expect_ident();
        let mut entries = Vec::new();
        if self.at(TokenKind::LBrace) {
            let open = self.bump();
            loop {
                if matches!(self.kind(), TokenKind::RBrace | TokenKind::Eof) || self.at_item_line()
                {
                    break;
                }
                let before = self.pos;
                entries.extend(self.entry());
                if self.pos == before {
                    self.bump();
                }
            }
            self.expect_close(TokenKind::RBrace, open);
        } else {
            self.expected(Expected::Token(TokenKind::LBrace), None);
        }
        match name {
            Some(name) => ItemKind::Scene(SceneDecl { name, entries }),
            None => ItemKind::Error,
        }
    }

    /// One entry, or `None` after an error that left nothing to keep.
    fn entry(&mut self) -> Option<SceneEntry> {
        let lo = self.span();
        let kind = match self.kind() {
            TokenKind::Let => {
                self.bump();
                let name = self.expect_ident();
                let value = if name.is_some() && self.expect(TokenKind::Eq) {
                    self.expr(Restrict::NONE)
                } else {
                    self.recover_entry();
                    return None;
                };
                self.expect_semi();
                SceneEntryKind::Let { name: name?, value }
            }
            TokenKind::Ident => match self.cur_text() {
                "settings" => {
                    self.bump();
                    SceneEntryKind::Settings(self.entry_fields()?)
                }
                "camera" => {
                    self.bump();
                    SceneEntryKind::Camera(self.expr(Restrict::NONE))
                }
                "background" => {
                    self.bump();
                    SceneEntryKind::Background(self.expr(Restrict::NONE))
                }
                "object" => {
                    self.bump();
                    let name = (self.at(TokenKind::Ident) && self.nth(1) == TokenKind::LBrace)
                        .then(|| self.ident());
                    let fields = self.entry_fields()?;
                    SceneEntryKind::Object { name, fields }
                }
                "light" => {
                    self.bump();
                    let name = (self.at(TokenKind::Ident) && self.nth(1) == TokenKind::Ident)
                        .then(|| self.ident());
                    let value = self.expr(Restrict::NONE);
                    SceneEntryKind::Light { name, value }
                }
                "model" => self.model()?,
                "animate" => self.animate()?,
                word => {
                    let suggestion =
                        crate::diag::suggest::closest(word, SCENE_ENTRIES.iter().copied());
                    let e = SyntaxError::UnknownSceneEntry {
                        name: word.to_string(),
                        suggestion,
                        span: lo,
                    };
                    self.error_here(e);
                    self.bump();
                    self.recover_entry();
                    return None;
                }
            },
            TokenKind::Semi => {
                self.expected(Expected::SceneEntry, Some(Hint::SceneEntryNoSemicolon));
                self.bump();
                return None;
            }
            k if ITEM_START.contains(k) => {
                self.report(SyntaxError::MisplacedItem {
                    keyword: k,
                    place: Place::Scene,
                    span: lo,
                });
                self.nested_item();
                self.last_error_pos = self.pos;
                return None;
            }
            _ => {
                self.expected(Expected::SceneEntry, None);
                self.bump();
                self.recover_entry();
                return None;
            }
        };
        Some(SceneEntry {
            kind,
            span: self.since(lo),
        })
    }

    /// `model "path" ({ fields })?`
    fn model(&mut self) -> Option<SceneEntryKind> {
        self.bump();
        if !self.at(TokenKind::Str) {
            self.expected(Expected::Path, None);
            self.recover_entry();
            return None;
        }
        let path_span = self.bump();
        let path = lexer::unescape(self.text(path_span));
        let fields = if self.at(TokenKind::LBrace) {
            self.field_inits()
        } else {
            Vec::new()
        };
        Some(SceneEntryKind::Model {
            path,
            path_span,
            fields,
        })
    }

    /// `animate name(.name)? (keys interp? { time: value, … } | name(args))`
    fn animate(&mut self) -> Option<SceneEntryKind> {
        self.bump();
        let mut target = vec![self.expect_ident().or_else(|| {
            self.recover_entry();
            None
        })?];
        if self.eat(TokenKind::Dot).is_some() {
            match self.expect_ident() {
                Some(field) => target.push(field),
                None => {
                    self.recover_entry();
                    return None;
                }
            }
        }
        if !self.at(TokenKind::Ident) {
            self.expected(Expected::Motion, None);
            self.recover_entry();
            return None;
        }
        let lo = self.span();
        let name = self.ident();
        let motion = if self.at(TokenKind::LParen) {
            let args = self.call_args();
            AnimMotion::Over {
                name,
                args,
                span: self.since(lo),
            }
        } else {
            let interp = self.at(TokenKind::Ident).then(|| self.ident());
            if !self.at(TokenKind::LBrace) {
                self.expected(Expected::Token(TokenKind::LBrace), None);
                self.recover_entry();
                return None;
            }
            let open = self.bump();
            let stop = TokenSet::new(&[TokenKind::Semi]);
            let keys = self.list(TokenKind::RBrace, stop, None, |p| {
                let time = p.expr(Restrict::NONE);
                if !p.expect(TokenKind::Colon) {
                    return None;
                }
                let value = p.expr(Restrict::NONE);
                Some(Keyframe { time, value })
            });
            self.expect_close(TokenKind::RBrace, open);
            // `kees { … }` is parsed as keys; sema reports the unknown word.
            AnimMotion::Keys {
                word: name,
                interp,
                keys,
                span: self.since(lo),
            }
        };
        Some(SceneEntryKind::Animate { target, motion })
    }

    /// `{ field_inits }` after `settings` or `object`.
    fn entry_fields(&mut self) -> Option<Vec<crate::syntax::ast::FieldInit>> {
        if self.at(TokenKind::LBrace) {
            return Some(self.field_inits());
        }
        self.expected(Expected::Token(TokenKind::LBrace), None);
        self.recover_entry();
        None
    }

    /// Skips to the start of the next entry (an entry keyword or `let`), or the scene's `}`,
    /// outside any group. Reports nothing.
    fn recover_entry(&mut self) {
        let mut nest = 0usize;
        loop {
            let k = self.kind();
            if k == TokenKind::Eof || self.at_item_line() {
                return;
            }
            if nest == 0 {
                let entry_word = k == TokenKind::Ident && SCENE_ENTRIES.contains(&self.cur_text());
                if k == TokenKind::RBrace || k == TokenKind::Let || entry_word {
                    return;
                }
            }
            match k {
                TokenKind::LParen | TokenKind::LBracket | TokenKind::LBrace => nest += 1,
                TokenKind::RParen | TokenKind::RBracket | TokenKind::RBrace => {
                    nest = nest.saturating_sub(1)
                }
                _ => {}
            }
            self.bump();
        }
    }
}
