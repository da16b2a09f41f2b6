//! A readable listing of the typed HIR (`rtc compile --emit hir`): source-like text with the types
//! the checker resolved.
//!
//! What the listing shows that the source may not: every local's type (`let x: f32 = …`), every
//! literal with its concrete type (`1.0` is `f32`, `1u` is `u32`, `1i` is `i32`), what the checker
//! made explicit (conversions and splats as constructors `f32(x)`, `vec3f(x)`; zero values as `T()`;
//! struct literals with every field, an omitted one filled with its default; every constant
//! evaluated), each program's attribute with its bounds, and each scene as the values it evaluates to.
//! Nested binary operations are parenthesised, so the tree's shape is visible without precedence
//! rules.
//!
//! Guarantees: the walk is exhaustive over the HIR's kinds (a new kind does not compile until it is
//! printed), it follows the program's arenas in order, and so the same program gives the same text.
//! Asset paths are shown relative to the folder of the module that names them, so a listing does not
//! depend on where the sources live. The text is for reading; it is not meant to be parsed again.

use super::{
    Block, Body, ConstValue, ExprId, ExprKind, FnId, Geometry, Instance, Interp, Literal,
    MeshAsset, ModuleId, Motion, Program, Scalar, SceneDesc, Stmt, StmtKind, Struct, TextureAsset,
    TrackTarget,
};
use crate::sema::types::{Type, TypeId};
use std::fmt::Write;
use std::path::Path;

/// The listing of every module of `program`, in load order.
pub fn program(program: &Program) -> String {
    let mut out = String::new();
    for i in 0..program.modules.len() {
        if i > 0 {
            out.push('\n');
        }
        out.push_str(&module(program, ModuleId(i as u32)));
    }
    out
}

/// The listing of one module: a header naming it and its imports, then its structs, constants,
/// functions and scenes, each group in declaration order.
pub fn module(program: &Program, id: ModuleId) -> String {
    let Some(m) = program.modules.get(id.index()) else {
        return String::new();
    };
    let mut p = Printer {
        program,
        out: String::new(),
        indent: 0,
        dir: m.path.as_deref().and_then(Path::parent),
    };
    let what = if m.is_prelude {
        " (prelude)"
    } else if m.is_root {
        " (root)"
    } else {
        ""
    };
    p.line(&format!("// module {}{what}", m.name));
    for &i in &m.imports {
        let name = program
            .modules
            .get(i.index())
            .map(|m| m.name.as_str())
            .unwrap_or("?");
        p.line(&format!("import \"{name}\";"));
    }
    for &s in &m.structs {
        p.out.push('\n');
        p.structure(&program.structs[s]);
    }
    if !m.consts.is_empty() {
        p.out.push('\n');
    }
    for &c in &m.consts {
        let c = &program.consts[c];
        let value = p.value(&c.value);
        p.line(&format!("const {}: {} = {value};", c.name, p.ty(c.ty)));
    }
    for &f in &m.functions {
        p.out.push('\n');
        p.function(f);
    }
    for &s in &m.scenes {
        p.out.push('\n');
        p.scene(&program.scenes[s]);
    }
    p.out
}

struct Printer<'p> {
    program: &'p Program,
    out: String,
    indent: usize,
    /// The folder asset paths are shown relative to.
    dir: Option<&'p Path>,
}

impl Printer<'_> {
    fn line(&mut self, text: &str) {
        for _ in 0..self.indent {
            self.out.push_str("    ");
        }
        self.out.push_str(text);
        self.out.push('\n');
    }

    fn ty(&self, ty: TypeId) -> String {
        self.program.type_name(ty)
    }

    fn structure(&mut self, s: &Struct) {
        if let Some(role) = s.role {
            self.line(&format!("@{}", role.name()));
        }
        self.line(&format!("struct {} {{", s.name));
        self.indent += 1;
        for f in &s.fields {
            let default = match &f.default {
                Some(v) => format!(" = {}", self.value(v)),
                None => String::new(),
            };
            self.line(&format!("{}: {}{default},", f.name, self.ty(f.ty)));
        }
        self.indent -= 1;
        self.line("}");
        for (kind, f) in &s.programs {
            let name = &self.program.functions[*f].name;
            self.line(&format!("// @{} program: fn {name}", kind.name()));
        }
    }

    fn function(&mut self, id: FnId) {
        let f = &self.program.functions[id];
        if let Some(kind) = f.program {
            let entry = self
                .program
                .programs
                .iter()
                .find(|e| e.func == id && e.kind == kind);
            let mut attr = format!("@{}", kind.name());
            if let Some(e) = entry {
                if e.samples > 1 {
                    attr.push_str(&format!("(samples = {})", e.samples));
                }
                if e.spawn_bound > 0 {
                    attr.push_str(&format!(" // spawn bound: {}", e.spawn_bound));
                }
            }
            self.line(&attr);
        }
        let params: Vec<String> = f
            .params
            .iter()
            .map(|&l| {
                let local = &f.body.locals[l];
                format!("{}: {}", local.name, self.ty(local.ty))
            })
            .collect();
        let ret = match self.program.types.get(f.ret) {
            Type::Void => String::new(),
            _ => format!(" -> {}", self.ty(f.ret)),
        };
        self.line(&format!("fn {}({}){ret} {{", f.name, params.join(", ")));
        self.block_body(&f.body, &f.block);
        self.line("}");
    }

    /// The statements of `block`, one level deeper.
    fn block_body(&mut self, body: &Body, block: &Block) {
        self.indent += 1;
        for s in &block.stmts {
            self.stmt(body, s);
        }
        self.indent -= 1;
    }

    fn stmt(&mut self, body: &Body, s: &Stmt) {
        let e = |p: &Self, id: ExprId| p.expr(body, id, false);
        match &s.kind {
            StmtKind::Let { local, value } => {
                let l = &body.locals[*local];
                let text = format!("let {}: {} = {};", l.name, self.ty(l.ty), e(self, *value));
                self.line(&text);
            }
            StmtKind::Var { local, value } => {
                let l = &body.locals[*local];
                let text = match value {
                    Some(v) => format!("var {}: {} = {};", l.name, self.ty(l.ty), e(self, *v)),
                    None => format!("var {}: {};", l.name, self.ty(l.ty)),
                };
                self.line(&text);
            }
            StmtKind::Assign { place, op, value } => {
                let op = op.map(|o| o.as_str()).unwrap_or("");
                let text = format!("{} {op}= {};", e(self, *place), e(self, *value));
                self.line(&text);
            }
            StmtKind::Expr(x) => {
                let text = format!("{};", e(self, *x));
                self.line(&text);
            }
            StmtKind::If {
                cond,
                then_block,
                else_block,
            } => {
                let text = format!("if {} {{", e(self, *cond));
                self.line(&text);
                self.block_body(body, then_block);
                if let Some(b) = else_block {
                    self.line("} else {");
                    self.block_body(body, b);
                }
                self.line("}");
            }
            StmtKind::For {
                var,
                start,
                end,
                body: b,
            } => {
                let l = &body.locals[*var];
                let text = format!(
                    "for {}: {} in {}..{} {{",
                    l.name,
                    self.ty(l.ty),
                    e(self, *start),
                    e(self, *end)
                );
                self.line(&text);
                self.block_body(body, b);
                self.line("}");
            }
            StmtKind::While { cond, body: b } => {
                let text = format!("while {} {{", e(self, *cond));
                self.line(&text);
                self.block_body(body, b);
                self.line("}");
            }
            StmtKind::Loop { body: b } => {
                self.line("loop {");
                self.block_body(body, b);
                self.line("}");
            }
            StmtKind::Break => self.line("break;"),
            StmtKind::Continue => self.line("continue;"),
            StmtKind::Return(None) => self.line("return;"),
            StmtKind::Return(Some(x)) => {
                let text = format!("return {};", e(self, *x));
                self.line(&text);
            }
            StmtKind::Block(b) => {
                self.line("{");
                self.block_body(body, b);
                self.line("}");
            }
        }
    }

    /// An expression; `nested` parenthesises a binary operation (an operand of another operator).
    fn expr(&self, body: &Body, id: ExprId, nested: bool) -> String {
        let x = &body.exprs[id];
        let list = |args: &[ExprId]| -> String {
            let parts: Vec<String> = args.iter().map(|&a| self.expr(body, a, false)).collect();
            parts.join(", ")
        };
        match &x.kind {
            ExprKind::Literal(l) => literal(l),
            ExprKind::Local(l) => body.locals[*l].name.clone(),
            ExprKind::Const(c) => self.program.consts[*c].name.clone(),
            ExprKind::Value(v) => self.value(v),
            ExprKind::Unary { op, operand } => {
                format!("{}{}", op.as_str(), self.expr(body, *operand, true))
            }
            ExprKind::Binary { op, lhs, rhs } => {
                let text = format!(
                    "{} {} {}",
                    self.expr(body, *lhs, true),
                    op.as_str(),
                    self.expr(body, *rhs, true)
                );
                if nested {
                    format!("({text})")
                } else {
                    text
                }
            }
            ExprKind::Call { func, args } => {
                format!("{}({})", self.program.functions[*func].name, list(args))
            }
            ExprKind::Builtin { func, args } => format!("{}({})", func.name(), list(args)),
            ExprKind::Compose { components } => match self.program.types.get(x.ty) {
                Type::Struct(s) => {
                    let st = &self.program.structs[s];
                    let fields: Vec<String> = st
                        .fields
                        .iter()
                        .zip(components)
                        .map(|(f, &c)| format!("{}: {}", f.name, self.expr(body, c, false)))
                        .collect();
                    format!("{} {{ {} }}", st.name, fields.join(", "))
                }
                _ => format!("{}({})", self.ty(x.ty), list(components)),
            },
            ExprKind::Splat { value } | ExprKind::Convert { arg: value } => {
                format!("{}({})", self.ty(x.ty), self.expr(body, *value, false))
            }
            ExprKind::Zero => format!("{}()", self.ty(x.ty)),
            ExprKind::Bitcast { arg } => {
                format!(
                    "bitcast<{}>({})",
                    self.ty(x.ty),
                    self.expr(body, *arg, false)
                )
            }
            ExprKind::Field { base, index } => {
                let base_ty = body.exprs[*base].ty;
                let name = self
                    .program
                    .struct_of(base_ty)
                    .and_then(|s| self.program.structs[s].fields.get(*index as usize))
                    .map(|f| f.name.clone())
                    .unwrap_or_else(|| index.to_string());
                format!("{}.{name}", self.expr(body, *base, true))
            }
            ExprKind::Swizzle { base, pattern, len } => {
                let comps: String = pattern
                    .iter()
                    .take(*len as usize)
                    .map(|&c| ['x', 'y', 'z', 'w'].get(c as usize).copied().unwrap_or('?'))
                    .collect();
                format!("{}.{comps}", self.expr(body, *base, true))
            }
            ExprKind::Index { base, index } => format!(
                "{}[{}]",
                self.expr(body, *base, true),
                self.expr(body, *index, false)
            ),
            ExprKind::Error => "{error}".to_string(),
        }
    }

    /// A constant value, written as a constructor of its type.
    fn value(&self, v: &ConstValue) -> String {
        match v {
            ConstValue::Scalar(s) => scalar(*s),
            ConstValue::Vector { len, comps } => {
                let kind = match comps[0] {
                    Scalar::Bool(_) => 'b',
                    Scalar::I32(_) => 'i',
                    Scalar::U32(_) => 'u',
                    Scalar::F32(_) => 'f',
                };
                let parts: Vec<String> = comps
                    .iter()
                    .take(*len as usize)
                    .map(|s| scalar(*s))
                    .collect();
                format!("vec{len}{kind}({})", parts.join(", "))
            }
            ConstValue::Matrix { cols, rows, data } => {
                let columns: Vec<String> = data
                    .iter()
                    .take(*cols as usize)
                    .map(|c| {
                        let parts: Vec<String> =
                            c.iter().take(*rows as usize).map(|&x| float(x)).collect();
                        format!("vec{rows}f({})", parts.join(", "))
                    })
                    .collect();
                format!("mat{cols}x{rows}f({})", columns.join(", "))
            }
            ConstValue::Array(items) => {
                let parts: Vec<String> = items.iter().map(|i| self.value(i)).collect();
                format!("array({})", parts.join(", "))
            }
            ConstValue::Struct { id, fields } => self.fields(&self.program.structs[*id], fields),
            ConstValue::Mesh(m) => self.mesh(m),
            ConstValue::Texture(TextureAsset::File { path, .. }) => {
                format!("load_image(\"{}\")", self.path(path))
            }
            ConstValue::Texture(TextureAsset::Solid(c)) => {
                let parts: Vec<String> = c.iter().map(|&x| float(x)).collect();
                format!("solid_texture(vec4f({}))", parts.join(", "))
            }
            ConstValue::String(s) => format!("{s:?}"),
            ConstValue::Error => "{error}".to_string(),
        }
    }

    /// `Name { a: 1.0, b: … }` (`Name {}` without fields).
    fn fields(&self, s: &Struct, values: &[ConstValue]) -> String {
        let parts: Vec<String> = s
            .fields
            .iter()
            .zip(values)
            .map(|(f, v)| format!("{}: {}", f.name, self.value(v)))
            .collect();
        if parts.is_empty() {
            format!("{} {{}}", s.name)
        } else {
            format!("{} {{ {} }}", s.name, parts.join(", "))
        }
    }

    fn instance(&self, i: &Instance) -> String {
        self.fields(&self.program.structs[i.struct_id], &i.fields)
    }

    fn mesh(&self, m: &MeshAsset) -> String {
        match m {
            MeshAsset::File { path, .. } => format!("load_mesh(\"{}\")", self.path(path)),
            MeshAsset::Quad => "quad_mesh()".to_string(),
            MeshAsset::Cube => "cube_mesh()".to_string(),
            MeshAsset::Sphere { subdivisions } => format!("sphere_mesh({subdivisions}u)"),
        }
    }

    /// An asset path relative to the module's folder when it is inside it, `/` separated.
    fn path(&self, path: &Path) -> String {
        let shown = self
            .dir
            .and_then(|d| path.strip_prefix(d).ok())
            .unwrap_or(path);
        shown.to_string_lossy().replace('\\', "/")
    }

    fn scene(&mut self, s: &SceneDesc) {
        self.line(&format!("scene {} {{", s.name));
        self.indent += 1;
        let st = &s.settings;
        let roulette = if st.roulette_depth == super::Settings::default().roulette_depth {
            String::new()
        } else {
            format!("roulette_depth: {}, ", st.roulette_depth)
        };
        self.line(&format!(
            "settings {{ width: {}, height: {}, samples: {}, max_depth: {}, max_rays_per_hit: {}, \
             {roulette}seed: {}, exec: {} }}",
            st.width, st.height, st.samples, st.max_depth, st.max_rays_per_hit, st.seed, st.exec
        ));
        if let Some(c) = &s.camera {
            let text = format!("camera {}", self.instance(c));
            self.line(&text);
        }
        if let Some(b) = &s.background {
            let text = format!("background {}", self.instance(b));
            self.line(&text);
        }
        for o in &s.objects {
            let name = o
                .name
                .as_deref()
                .map(|n| format!(" {n}"))
                .unwrap_or_default();
            let geometry = match &o.geometry {
                Geometry::Mesh(m) => self.mesh(m),
                Geometry::Custom(i) => self.instance(i),
            };
            let text = format!("object{name} {{");
            self.line(&text);
            self.indent += 1;
            let lines = [
                format!("geometry: {geometry},"),
                format!("material: {},", self.instance(&o.material)),
                format!("transform: {},", matrix4(&o.transform)),
            ];
            for l in lines {
                self.line(&l);
            }
            self.indent -= 1;
            self.line("}");
        }
        for l in &s.lights {
            let text = format!("light {}", self.instance(l));
            self.line(&text);
        }
        for m in &s.models {
            let text = format!(
                "model \"{}\" {{ transform: {} }}",
                self.path(&m.path),
                matrix4(&m.transform)
            );
            self.line(&text);
        }
        if !s.animation.is_empty() {
            let text = format!(
                "animation {{ fps: {}, frames: {} }}",
                s.settings.fps, s.settings.frames
            );
            self.line(&text);
        }
        for t in &s.animation {
            let target = match &t.target {
                TrackTarget::Object(i) => match &s.objects[*i].name {
                    Some(n) => n.clone(),
                    None => format!("object#{i}"),
                },
                TrackTarget::Camera { name, .. } => format!("camera.{name}"),
                TrackTarget::Background { name, .. } => format!("background.{name}"),
                TrackTarget::Light { light, name, .. } => format!("light#{light}.{name}"),
            };
            let motion = match &t.motion {
                Motion::Keys {
                    times,
                    values,
                    interp,
                } => {
                    let keys: Vec<String> = times
                        .iter()
                        .zip(values)
                        .map(|(t, v)| format!("{}: {}", float(*t), self.value(v)))
                        .collect();
                    let interp = match interp {
                        Interp::Linear => "linear",
                        Interp::Step => "step",
                        Interp::Smooth => "smooth",
                    };
                    format!("keys {interp} {{ {} }}", keys.join(", "))
                }
                Motion::Spin {
                    axis,
                    degrees_per_second,
                    pivot,
                } => format!(
                    "spin(vec3f({}, {}, {}), {}, vec3f({}, {}, {}))",
                    float(axis[0]),
                    float(axis[1]),
                    float(axis[2]),
                    float(*degrees_per_second),
                    float(pivot[0]),
                    float(pivot[1]),
                    float(pivot[2])
                ),
                Motion::Move { velocity } => format!(
                    "move(vec3f({}, {}, {}))",
                    float(velocity[0]),
                    float(velocity[1]),
                    float(velocity[2])
                ),
            };
            let text = format!("animate {target} {motion}");
            self.line(&text);
        }
        self.indent -= 1;
        self.line("}");
    }
}

fn literal(l: &Literal) -> String {
    match l {
        Literal::Bool(b) => b.to_string(),
        Literal::I32(i) => format!("{i}i"),
        Literal::U32(u) => format!("{u}u"),
        Literal::F32(f) => float(*f),
        Literal::String(s) => format!("{s:?}"),
    }
}

fn scalar(s: Scalar) -> String {
    match s {
        Scalar::Bool(b) => b.to_string(),
        Scalar::I32(i) => format!("{i}i"),
        Scalar::U32(u) => format!("{u}u"),
        Scalar::F32(f) => float(f),
    }
}

/// The shortest text that reads back as the same `f32` (`1.0`, `0.1`, `1e-7`, `inf`, `NaN`).
fn float(x: f32) -> String {
    let mut s = String::new();
    let _ = write!(s, "{x:?}");
    s
}

/// A column-major 4×4 matrix as `mat4x4f(columns)`.
fn matrix4(m: &[[f32; 4]; 4]) -> String {
    let columns: Vec<String> = m
        .iter()
        .map(|c| {
            let parts: Vec<String> = c.iter().map(|&x| float(x)).collect();
            format!("vec4f({})", parts.join(", "))
        })
        .collect();
    format!("mat4x4f({})", columns.join(", "))
}

#[cfg(test)]
mod tests {
    use crate::driver::{check_text, Options};

    #[test]
    fn a_function_prints_as_typed_source() {
        let src = "struct P { a: vec3f, b: f32 = 2.0 }\n\
                   fn f(p: P, i: u32) -> f32 {\n\
                   \x20   var s = 0.0;\n\
                   \x20   for k in 0u..i { s += p.a.y * f32(k) + 1.0; }\n\
                   \x20   let q = P { a: vec3f(s) };\n\
                   \x20   return q.b;\n\
                   }\n";
        let c = check_text("t.rt", src, &Options::default());
        let p = c.program.as_ref().expect("checks");
        let root = p
            .modules
            .iter()
            .position(|m| m.is_root)
            .expect("a root module");
        let text = super::module(p, super::ModuleId(root as u32));
        let want = "// module t.rt (root)\n\
                    \n\
                    struct P {\n\
                    \x20   a: vec3f,\n\
                    \x20   b: f32 = 2.0,\n\
                    }\n\
                    \n\
                    fn f(p: P, i: u32) -> f32 {\n\
                    \x20   var s: f32 = 0.0;\n\
                    \x20   for k: u32 in 0u..i {\n\
                    \x20       s += (p.a.y * f32(k)) + 1.0;\n\
                    \x20   }\n\
                    \x20   let q: P = P { a: vec3f(s), b: 2.0 };\n\
                    \x20   return q.b;\n\
                    }\n";
        assert_eq!(text, want);
    }
}
