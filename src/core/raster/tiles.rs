//! The square tiles an image is split into by the host rasterizers: how many there are, which
//! pixels each covers, and which tiles a surfel's pixel box overlaps.

/// An image of `width × height` pixels cut into `size × size` tiles, row-major.
#[derive(Clone, Copy, Debug)]
pub(crate) struct TileGrid {
    pub(crate) size: usize,
    pub(crate) nx: usize,
    pub(crate) ny: usize,
    pub(crate) width: usize,
    pub(crate) height: usize,
}

impl TileGrid {
    pub(crate) fn new(width: usize, height: usize, size: usize) -> Self {
        TileGrid {
            size,
            nx: width.div_ceil(size),
            ny: height.div_ceil(size),
            width,
            height,
        }
    }

    pub(crate) fn count(&self) -> usize {
        self.nx * self.ny
    }

    /// Pixels of a whole tile (the last row and column of tiles may hold fewer in the image).
    pub(crate) fn pixels(&self) -> usize {
        self.size * self.size
    }

    /// Pixel bounds `[x0, y0, x1, y1)` of tile `t`, clipped to the image.
    pub(crate) fn bounds(&self, t: usize) -> [usize; 4] {
        let (tx, ty) = (t % self.nx, t / self.nx);
        let (x0, y0) = (tx * self.size, ty * self.size);
        [
            x0,
            y0,
            (x0 + self.size).min(self.width),
            (y0 + self.size).min(self.height),
        ]
    }

    /// Tiles `[tx0, ty0, tx1, ty1)` overlapped by a (non-empty) pixel box.
    pub(crate) fn tiles_of(&self, rect: [u32; 4]) -> [usize; 4] {
        let s = self.size;
        [
            rect[0] as usize / s,
            rect[1] as usize / s,
            (rect[2] as usize - 1) / s + 1,
            (rect[3] as usize - 1) / s + 1,
        ]
    }
}
