//! Hand-built constant tables (fxc's `CTAB` comment blocks) for the tests:
//! a table is described as constants and types, and laid out here the way
//! D3DX lays one out (header, constant infos, then each constant's type,
//! members, name and default, then creator and target strings; every offset
//! from the start of the table). Written from the structure definitions of
//! d3dx9shader.h, independently of ps30's decoder.

// Not every test crate that includes this module uses every function.

/// A D3DXSHADER_TYPEINFO to lay out.
#[derive(Clone, Debug)]
pub struct Ty {
    pub class: u16,
    pub base: u16,
    pub rows: u16,
    pub columns: u16,
    pub elements: u16,
    pub members: Vec<(&'static str, Ty)>,
}

impl Ty {
    /// A scalar, vector or matrix (class 0 to 3) of `base` (1 bool, 2 int, 3 float).
    pub fn numeric(class: u16, base: u16, rows: u16, columns: u16, elements: u16) -> Ty {
        Ty {
            class,
            base,
            rows,
            columns,
            elements,
            members: Vec::new(),
        }
    }

    /// An object (a sampler: base 10 to 14).
    pub fn object(base: u16) -> Ty {
        Ty::numeric(4, base, 1, 1, 1)
    }

    pub fn structure(elements: u16, members: Vec<(&'static str, Ty)>) -> Ty {
        Ty {
            class: 5,
            base: 0,
            rows: 1,
            columns: members.len() as u16,
            elements,
            members,
        }
    }
}

/// A D3DXSHADER_CONSTANTINFO to lay out.
#[derive(Clone, Debug)]
pub struct Const {
    pub name: &'static str,
    /// 0 bool, 1 int4, 2 float4, 3 sampler.
    pub set: u16,
    pub index: u16,
    pub count: u16,
    pub ty: Ty,
    pub default: Option<Vec<u32>>,
}

struct Out {
    bytes: Vec<u8>,
}

impl Out {
    fn at(&self) -> u32 {
        self.bytes.len() as u32
    }

    fn u32(&mut self, v: u32) {
        self.bytes.extend(v.to_le_bytes());
    }

    fn u16(&mut self, v: u16) {
        self.bytes.extend(v.to_le_bytes());
    }

    fn set_u32(&mut self, at: u32, v: u32) {
        self.bytes[at as usize..at as usize + 4].copy_from_slice(&v.to_le_bytes());
    }

    /// A zero-ended string padded to 4 bytes; returns its offset.
    fn string(&mut self, s: &str) -> u32 {
        let at = self.at();
        self.bytes.extend(s.as_bytes());
        self.bytes.push(0);
        while !self.bytes.len().is_multiple_of(4) {
            self.bytes.push(0xab);
        }
        at
    }

    /// A type info with its members after it; returns its offset.
    fn ty(&mut self, t: &Ty) -> u32 {
        let at = self.at();
        self.u16(t.class);
        self.u16(t.base);
        self.u16(t.rows);
        self.u16(t.columns);
        self.u16(t.elements);
        self.u16(t.members.len() as u16);
        self.u32(0);
        if !t.members.is_empty() {
            let members = self.at();
            self.set_u32(at + 12, members);
            for _ in &t.members {
                self.u32(0);
                self.u32(0);
            }
            for (i, (name, mt)) in t.members.iter().enumerate() {
                let n = self.string(name);
                let m = self.ty(mt);
                self.set_u32(members + 8 * i as u32, n);
                self.set_u32(members + 8 * i as u32 + 4, m);
            }
        }
        at
    }
}

/// The comment body of a constant table: `CTAB` and the table.
pub fn table(creator: &str, target: &str, version: u32, constants: &[Const]) -> Vec<u32> {
    let mut o = Out { bytes: Vec::new() };
    for v in [28, 0, version, constants.len() as u32, 28, 0, 0] {
        o.u32(v);
    }
    let infos = o.at();
    for c in constants {
        o.u32(0);
        o.u16(c.set);
        o.u16(c.index);
        o.u16(c.count);
        o.u16(0);
        o.u32(0);
        o.u32(0);
    }
    for (i, c) in constants.iter().enumerate() {
        let info = infos + 20 * i as u32;
        let name = o.string(c.name);
        o.set_u32(info, name);
        let ty = o.ty(&c.ty);
        o.set_u32(info + 12, ty);
        if let Some(d) = &c.default {
            let at = o.at();
            d.iter().for_each(|&w| o.u32(w));
            o.set_u32(info + 16, at);
        }
    }
    let creator = o.string(creator);
    o.set_u32(4, creator);
    let target = o.string(target);
    o.set_u32(24, target);
    let mut body = vec![u32::from_le_bytes(*b"CTAB")];
    body.extend(
        o.bytes
            .chunks(4)
            .map(|b| u32::from_le_bytes([b[0], b[1], b[2], b[3]])),
    );
    body
}

/// A comment token for a body.
pub fn comment(body: &[u32]) -> Vec<u32> {
    let mut t = vec![0xfffe | (body.len() as u32) << 16];
    t.extend(body);
    t
}

/// A body as `//#comment` lines of the listing syntax.
pub fn comment_lines(body: &[u32]) -> String {
    let mut out = String::new();
    for (i, chunk) in body.chunks(8).enumerate() {
        out.push_str(if i == 0 { "//#comment" } else { "//#+" });
        for t in chunk {
            out.push_str(&format!(" {t:08x}"));
        }
        out.push('\n');
    }
    out
}
