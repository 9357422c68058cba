//! Cube and volume textures: the two Direct3D 9 texture types that are not
//! one 2D image, each with its mip levels.
//!
//! They exist apart from [`MipChain`] because their shapes have rules of
//! their own, checked once when one is made so that samplers can index
//! without checks: a cube's six faces are square, of one size and one level
//! count (D3D9 `CreateCubeTexture` takes one edge length and one level count
//! for all faces); a volume's levels halve all three sides, each side
//! stopping at 1 (`CreateVolumeTexture`). Levels are kept as given, so
//! authored mips (a DDS file's) are read as the application wrote them.

use super::{MipChain, Texture};

/// The six faces of a cube texture in D3DCUBEMAP_FACES order (+X, −X, +Y,
/// −Y, +Z, −Z), each a square [`MipChain`].
#[derive(Clone, Debug, PartialEq)]
pub struct CubeMap {
    faces: Vec<MipChain>,
}

impl CubeMap {
    /// Six faces, checked: square, the same edge and the same number of levels.
    pub fn from_faces(faces: Vec<MipChain>) -> Result<CubeMap, String> {
        if faces.len() != 6 {
            return Err(format!("a cube texture has 6 faces, got {}", faces.len()));
        }
        let first = faces[0].level(0).expect("a chain has level 0");
        if first.width != first.height {
            return Err(format!(
                "cube faces are square; face 0 is {}x{}",
                first.width, first.height
            ));
        }
        for (i, f) in faces.iter().enumerate().skip(1) {
            let l = f.level(0).expect("a chain has level 0");
            if (l.width, l.height) != (first.width, first.height) || f.len() != faces[0].len() {
                return Err(format!(
                    "cube face {i} is {}x{} with {} levels; face 0 is {}x{} with {}",
                    l.width,
                    l.height,
                    f.len(),
                    first.width,
                    first.height,
                    faces[0].len()
                ));
            }
        }
        Ok(CubeMap { faces })
    }

    /// Face `i` (0 = +X … 5 = −Z).
    ///
    /// # Panics
    /// If `i >= 6`.
    pub fn face(&self, i: usize) -> &MipChain {
        &self.faces[i]
    }

    /// The edge length of level 0.
    pub fn edge(&self) -> u32 {
        self.faces[0].level(0).map_or(0, |l| l.width)
    }
}

/// One level of a volume texture: `depth` slices of `width × height`
/// texels, slice 0 first, each row-major with its top row first.
#[derive(Clone, Debug, PartialEq)]
pub struct VolumeLevel {
    /// Width in texels.
    pub width: u32,
    /// Height in texels.
    pub height: u32,
    /// Depth in slices.
    pub depth: u32,
    /// `width × height × depth` texels.
    pub texels: Vec<[f32; 4]>,
}

/// A volume texture with its mip levels, level 0 first.
#[derive(Clone, Debug, PartialEq)]
pub struct VolumeChain {
    levels: Vec<VolumeLevel>,
}

impl VolumeChain {
    /// Levels as given, checked: every next level halves each side (to at
    /// least 1) and each holds exactly its texels.
    pub fn from_levels(levels: Vec<VolumeLevel>) -> Result<VolumeChain, String> {
        for (i, l) in levels.iter().enumerate() {
            if l.width == 0 || l.height == 0 || l.depth == 0 {
                return Err(format!(
                    "level {i}: size {}x{}x{} is empty",
                    l.width, l.height, l.depth
                ));
            }
            let want = l.width as u64 * l.height as u64 * l.depth as u64;
            if l.texels.len() as u64 != want {
                return Err(format!(
                    "level {i}: {}x{}x{} needs {want} texels, got {}",
                    l.width,
                    l.height,
                    l.depth,
                    l.texels.len()
                ));
            }
            if i > 0 {
                let p = &levels[i - 1];
                let half = |n: u32| (n / 2).max(1);
                let want = (half(p.width), half(p.height), half(p.depth));
                if (l.width, l.height, l.depth) != want || (p.width, p.height, p.depth) == (1, 1, 1)
                {
                    return Err(format!(
                        "level {i} is {}x{}x{}; after {}x{}x{} a mip level is {}x{}x{}",
                        l.width,
                        l.height,
                        l.depth,
                        p.width,
                        p.height,
                        p.depth,
                        want.0,
                        want.1,
                        want.2
                    ));
                }
            }
        }
        if levels.is_empty() {
            return Err("a volume texture has at least one level".into());
        }
        Ok(VolumeChain { levels })
    }

    /// Number of levels (at least 1).
    pub fn len(&self) -> usize {
        self.levels.len()
    }

    /// Always false: a chain has level 0.
    pub fn is_empty(&self) -> bool {
        self.levels.is_empty()
    }

    /// Level `i`, if it exists.
    pub fn level(&self, i: usize) -> Option<&VolumeLevel> {
        self.levels.get(i)
    }

    /// Slice `z` of level `i` as a 2D view, if both exist.
    pub fn slice(&self, i: usize, z: u32) -> Option<Texture<'_>> {
        let l = self.levels.get(i)?;
        if z >= l.depth {
            return None;
        }
        let n = l.width as usize * l.height as usize;
        Some(Texture {
            width: l.width,
            height: l.height,
            texels: &l.texels[z as usize * n..(z as usize + 1) * n],
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn chain(side: u32, levels: u32) -> MipChain {
        let base = vec![[0.5; 4]; (side * side) as usize];
        MipChain::build(
            Texture {
                width: side,
                height: side,
                texels: &base,
            },
            Some(levels),
        )
        .unwrap()
    }

    #[test]
    fn cube_faces_must_match() {
        assert!(CubeMap::from_faces((0..6).map(|_| chain(4, 3)).collect()).is_ok());
        assert!(CubeMap::from_faces((0..5).map(|_| chain(4, 3)).collect()).is_err());
        let mut faces: Vec<_> = (0..6).map(|_| chain(4, 3)).collect();
        faces[3] = chain(4, 2);
        let e = CubeMap::from_faces(faces).unwrap_err();
        assert!(e.contains("face 3"), "{e}");
    }

    #[test]
    fn volume_levels_halve_every_side() {
        let l = |w: u32, h: u32, d: u32| VolumeLevel {
            width: w,
            height: h,
            depth: d,
            texels: vec![[0.0; 4]; (w * h * d) as usize],
        };
        assert!(VolumeChain::from_levels(vec![l(4, 2, 8), l(2, 1, 4), l(1, 1, 2)]).is_ok());
        let e = VolumeChain::from_levels(vec![l(4, 2, 8), l(2, 1, 8)]).unwrap_err();
        assert!(e.contains("level 1"), "{e}");
    }
}
