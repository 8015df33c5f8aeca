// Exclusive prefix sum of the per-surfel tile counts into the binning offsets, on the device (the
// resident trainer; the rasterizer backend scans on the host): `scan_blocks` scans each block of
// SCAN_BLOCK counts and writes the block's sum, `scan_sums` (one workgroup) scans the block sums,
// writes the entry total and sizes the indirect dispatches that follow, and `scan_add` adds each
// block's offset to its counts' offsets.
// Threading: SCAN_THREADS threads per workgroup, SCAN_ITEMS consecutive counts per thread, one
// workgroup per block on a 2-D grid (`scan_blocks`, `scan_add`); a single workgroup that walks
// the block sums in chunks (`scan_sums`). Workgroup memory: one u32 per thread.

const SCAN_THREADS: u32 = 256u;
const SCAN_ITEMS: u32 = 4u;
const SCAN_BLOCK: u32 = SCAN_THREADS * SCAN_ITEMS;
// Entries per radix-sort block (RADIX_BLOCK of radix_sort.wgsl) and threads per workgroup of the
// 1-D kernels, for the indirect dispatches.
const SORT_BLOCK: u32 = 2048u;
const GROUP_THREADS: u32 = 256u;

struct ScanParams {
    // Counts to scan.
    n: u32,
    // Entries the entry buffers hold.
    capacity: u32,
    // Most workgroups per grid dimension.
    max_groups: u32,
    pad0: u32,
}

@group(0) @binding(0) var<uniform> scan: ScanParams;
@group(0) @binding(1) var<storage, read> counts: array<u32>;
@group(0) @binding(2) var<storage, read_write> offsets: array<u32>;
@group(0) @binding(3) var<storage, read_write> block_sums: array<u32>;
// The step status of train_common.wgsl; its first words are the entries that fit (min(total,
// capacity), which the sort and the range kernels read), the total, and whether it overflowed.
@group(0) @binding(4) var<storage, read_write> status: array<u32>;
// Indirect dispatch grids (x, y, z): the radix sort's block kernels, then the per-entry kernels.
@group(0) @binding(5) var<storage, read_write> dispatch: array<u32>;

var<workgroup> partial: array<u32, SCAN_THREADS>;

// Exclusive scan of partial[] across the workgroup (Hillis–Steele on an inclusive copy);
// returns the workgroup's total. Call from uniform control flow.
fn scan_partial(t: u32) -> u32 {
    workgroupBarrier();
    let own = partial[t];
    for (var d = 1u; d < SCAN_THREADS; d = d << 1u) {
        var add = 0u;
        if t >= d {
            add = partial[t - d];
        }
        workgroupBarrier();
        partial[t] += add;
        workgroupBarrier();
    }
    let total = partial[SCAN_THREADS - 1u];
    let exclusive = partial[t] - own;
    workgroupBarrier();
    partial[t] = exclusive;
    workgroupBarrier();
    return total;
}

fn block_index(wg: vec3<u32>, nwg: vec3<u32>) -> u32 {
    return wg.x + wg.y * nwg.x;
}

@compute @workgroup_size(SCAN_THREADS)
fn scan_blocks(
    @builtin(workgroup_id) wg: vec3<u32>,
    @builtin(num_workgroups) nwg: vec3<u32>,
    @builtin(local_invocation_index) t: u32,
) {
    let block = block_index(wg, nwg);
    let start = block * SCAN_BLOCK + t * SCAN_ITEMS;
    var own = 0u;
    for (var k = 0u; k < SCAN_ITEMS; k++) {
        if start + k < scan.n {
            own += counts[start + k];
        }
    }
    partial[t] = own;
    let total = scan_partial(t);
    var run = partial[t];
    for (var k = 0u; k < SCAN_ITEMS; k++) {
        let i = start + k;
        if i < scan.n {
            offsets[i] = run;
            run += counts[i];
        }
    }
    if t == 0u && block * SCAN_BLOCK < scan.n {
        block_sums[block] = total;
    }
}

// A 2-D grid of at least `groups` workgroups, written at `dispatch[at..at + 3]`.
fn write_grid(at: u32, groups: u32) {
    let x = min(groups, scan.max_groups);
    var y = 0u;
    if x > 0u {
        y = (groups + x - 1u) / x;
    }
    dispatch[at] = x;
    dispatch[at + 1u] = y;
    dispatch[at + 2u] = 1u;
}

@compute @workgroup_size(SCAN_THREADS)
fn scan_sums(@builtin(local_invocation_index) t: u32) {
    let blocks = (scan.n + SCAN_BLOCK - 1u) / SCAN_BLOCK;
    var carry = 0u;
    for (var first = 0u; first < blocks; first += SCAN_THREADS) {
        let i = first + t;
        var own = 0u;
        if i < blocks {
            own = block_sums[i];
        }
        partial[t] = own;
        let total = scan_partial(t);
        if i < blocks {
            block_sums[i] = carry + partial[t];
        }
        carry += total;
    }
    if t == 0u {
        let fits = min(carry, scan.capacity);
        status[0] = fits;
        status[1] = carry;
        status[2] = u32(carry > scan.capacity);
        write_grid(0u, (fits + SORT_BLOCK - 1u) / SORT_BLOCK);
        write_grid(3u, (fits + GROUP_THREADS - 1u) / GROUP_THREADS);
    }
}

@compute @workgroup_size(SCAN_THREADS)
fn scan_add(
    @builtin(workgroup_id) wg: vec3<u32>,
    @builtin(num_workgroups) nwg: vec3<u32>,
    @builtin(local_invocation_index) t: u32,
) {
    let block = block_index(wg, nwg);
    let start = block * SCAN_BLOCK + t * SCAN_ITEMS;
    if start >= scan.n {
        return;
    }
    let offset = block_sums[block];
    for (var k = 0u; k < SCAN_ITEMS; k++) {
        if start + k < scan.n {
            offsets[start + k] += offset;
        }
    }
}
