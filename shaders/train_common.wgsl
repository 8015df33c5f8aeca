// Constants shared by the resident trainer's kernels (train_pixels.wgsl, train_loss.wgsl,
// train_update.wgsl): workgroup size and the layout of the step status (read back after every
// step). No bindings, no entry points.

const THREADS: u32 = 256u;
// Values per pixel of the rasterizer's G-buffers and of their upstream gradient (NUM_OUT of
// common.wgsl): α, depth, normal (3), albedo (3), roughness, IoR, squared depth.
const NUM_OUT: u32 = 11u;
const BIG_F: f32 = 3.0e38;

// Words of the step status. u32 words: the tile entries that fit their buffer (what the sort and
// the range kernels read, scan.wgsl), all tile entries, whether they overflowed the buffer, and
// whether the update left a non-finite parameter:
const STATUS_FITTING: u32 = 0u;
const STATUS_ENTRIES: u32 = 1u;
const STATUS_OVERFLOW: u32 = 2u;
const STATUS_NONFINITE: u32 = 3u;
// f32 sums (bit patterns) from SUM_FIRST on, in the order of the partial-sum slots:
const SUM_FIRST: u32 = 8u;
const SLOT_L1: u32 = 0u;
const SLOT_SSIM: u32 = 1u;
const SLOT_MASK: u32 = 2u;
const SLOT_STOKES: u32 = 3u;
const SLOT_SMOOTH: u32 = 4u;
const SLOT_DEPTH_NORMAL: u32 = 5u;
const SLOT_DEPTH_NORMAL_COUNT: u32 = 6u;
const SLOT_ANGLE: u32 = 7u;
const SLOT_DISTORTION: u32 = 8u;
const SLOT_AOLP: u32 = 9u;
const SLOTS: u32 = 10u;

