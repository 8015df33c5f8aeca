//! Bands of tile rows: an image whose per-pixel buffers or tile entries would exceed the device's
//! binding limit is rasterized one band of tile rows at a time (`super::raster`). The first
//! bands hold as many rows as the largest per-pixel buffer allows; a band whose entries then do
//! not fit is halved until they do.
//!
//! Threading: plain values, computed on the calling thread.

/// Tile edge of the device kernels (`TILE` in shaders/common.wgsl).
pub(super) const TILE: u32 = 8;

/// A band of tile rows `[first, end)`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) struct Band {
    pub(super) first: u32,
    pub(super) end: u32,
}

impl Band {
    /// The whole of an image of `height` pixel rows.
    pub(super) fn whole(height: u32) -> Self {
        Band {
            first: 0,
            end: height.div_ceil(TILE),
        }
    }

    /// The bands of an image of `height` pixel rows with at most `rows_per_band` tile rows
    /// each, top to bottom.
    pub(super) fn split(height: u32, rows_per_band: u32) -> Vec<Band> {
        let tile_rows = height.div_ceil(TILE);
        (0..tile_rows)
            .step_by(rows_per_band.max(1) as usize)
            .map(|first| Band {
                first,
                end: (first + rows_per_band.max(1)).min(tile_rows),
            })
            .collect()
    }

    pub(super) fn tile_rows(self) -> u32 {
        self.end - self.first
    }

    /// Pixel rows of the band in an image of `height` rows.
    pub(super) fn pixel_rows(self, height: u32) -> u32 {
        (self.end * TILE).min(height) - self.first * TILE
    }

    /// The band's rows of a row-major per-pixel array with `per_row` values per image row.
    pub(super) fn rows_of<T>(self, values: &[T], height: u32, per_row: usize) -> &[T] {
        let start = (self.first * TILE) as usize * per_row;
        &values[start..start + self.pixel_rows(height) as usize * per_row]
    }

    /// The top and bottom halves (the top one smaller when the rows are odd).
    pub(super) fn halves(self) -> (Band, Band) {
        let mid = self.first + self.tile_rows() / 2;
        (
            Band {
                first: self.first,
                end: mid,
            },
            Band {
                first: mid,
                end: self.end,
            },
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// 37 pixel rows are 5 tile rows (the last one partial): bands of 2 rows cover them in
    /// order, and their pixel rows add up to the image's.
    #[test]
    fn bands_cover_the_image_once_top_to_bottom() {
        let bands = Band::split(37, 2);
        assert_eq!(
            bands,
            vec![
                Band { first: 0, end: 2 },
                Band { first: 2, end: 4 },
                Band { first: 4, end: 5 },
            ]
        );
        assert_eq!(bands.iter().map(|b| b.pixel_rows(37)).sum::<u32>(), 37);
        assert_eq!(Band::split(37, 100), vec![Band::whole(37)]);
        let values: Vec<u32> = (0..37 * 3).collect();
        assert_eq!(bands[2].rows_of(&values, 37, 3), &values[32 * 3..]);
    }

    #[test]
    fn halves_split_the_rows() {
        let (top, bottom) = Band { first: 3, end: 8 }.halves();
        assert_eq!(
            (top, bottom),
            (Band { first: 3, end: 5 }, Band { first: 5, end: 8 })
        );
    }
}
