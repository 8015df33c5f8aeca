// Stable least-significant-digit radix sort of the binning entries (vec4<u32>: tile, depth bits,
// surfel) by (tile, depth), 4 bits per pass: passes over the depth bits that vary between the
// entries (the host skips digits that are the same in all), then over the tile bits the tile count
// needs. `emit` writes the entries in surfel order, and every pass is stable, so ties keep surfel
// order: each tile's run ends up front to back, ties broken by surfel index like the cpu backend.
// The number of entries is read from `sort_count[0]` (written by the host, or by the device scan
// of scan.wgsl, which also sizes the indirect dispatches of the block kernels).
// One pass is three kernels over blocks of RADIX_BLOCK entries (the host ping-pongs `keys_in` and
// `keys_out` between passes):
//   `radix_count`   per block, how many entries have each digit (per-thread counts summed with
//                   workgroup atomics), into `hist` (digit-major: hist[digit * blocks + block]);
//   `radix_scan`    one workgroup: exclusive scan of `hist`, so hist[d * blocks + b] becomes where
//                   block b's first entry with digit d goes;
//   `radix_scatter` per block, each thread ranks its own RADIX_ITEMS consecutive entries against
//                   the block's other threads (a workgroup scan of per-thread digit counts) and
//                   writes them to their sorted place, in order.
// Threading: RADIX_THREADS threads per workgroup; one workgroup per block on a 2-D grid for
// `radix_count` and `radix_scatter`, a single workgroup for `radix_scan`. Workgroup memory: the
// per-thread digit counts (RADIX_BINS × RADIX_THREADS u32, 8 KiB) and their scan.

const RADIX_BINS: u32 = 16u;
const RADIX_THREADS: u32 = 128u;
const RADIX_ITEMS: u32 = 16u;
const RADIX_BLOCK: u32 = RADIX_THREADS * RADIX_ITEMS;

struct RadixPass {
    // Bit offset of the digit within its key word.
    shift: u32,
    // Key word: 0 = depth bits (entry.y), 1 = tile (entry.x).
    word: u32,
    pad0: u32,
    pad1: u32,
}

@group(0) @binding(0) var<uniform> pass_: RadixPass;
@group(0) @binding(1) var<storage, read> keys_in: array<vec4<u32>>;
@group(0) @binding(2) var<storage, read_write> keys_out: array<vec4<u32>>;
@group(0) @binding(3) var<storage, read_write> hist: array<u32>;
@group(0) @binding(4) var<storage, read> sort_count: array<u32>;

var<workgroup> block_bins: array<atomic<u32>, RADIX_BINS>;
var<workgroup> thread_counts: array<u32, RADIX_BINS * RADIX_THREADS>;
var<workgroup> partial: array<u32, RADIX_THREADS>;

// Entries to sort (at most the buffers' capacity: the scan clamps it).
fn total() -> u32 {
    return sort_count[0];
}

// Blocks of RADIX_BLOCK entries: ceil(total / RADIX_BLOCK).
fn blocks() -> u32 {
    return (total() + RADIX_BLOCK - 1u) / RADIX_BLOCK;
}

fn digit(e: vec4<u32>) -> u32 {
    let word = select(e.y, e.x, pass_.word == 1u);
    return (word >> pass_.shift) & (RADIX_BINS - 1u);
}

fn block_index(wg: vec3<u32>, nwg: vec3<u32>) -> u32 {
    return wg.x + wg.y * nwg.x;
}

// How many of thread t's own RADIX_ITEMS consecutive entries of `block` have each digit.
fn own_digit_counts(block: u32, t: u32) -> array<u32, RADIX_BINS> {
    var counts: array<u32, RADIX_BINS>;
    for (var d = 0u; d < RADIX_BINS; d++) {
        counts[d] = 0u;
    }
    let start = block * RADIX_BLOCK + t * RADIX_ITEMS;
    for (var k = 0u; k < RADIX_ITEMS; k++) {
        let i = start + k;
        if i < total() {
            counts[digit(keys_in[i])] += 1u;
        }
    }
    return counts;
}

@compute @workgroup_size(RADIX_THREADS)
fn radix_count(
    @builtin(workgroup_id) wg: vec3<u32>,
    @builtin(num_workgroups) nwg: vec3<u32>,
    @builtin(local_invocation_index) t: u32,
) {
    let block = block_index(wg, nwg);
    if t < RADIX_BINS {
        atomicStore(&block_bins[t], 0u);
    }
    workgroupBarrier();
    let mine = own_digit_counts(block, t);
    for (var d = 0u; d < RADIX_BINS; d++) {
        if mine[d] != 0u {
            atomicAdd(&block_bins[d], mine[d]);
        }
    }
    workgroupBarrier();
    if t < RADIX_BINS && block < blocks() {
        hist[t * blocks() + block] = atomicLoad(&block_bins[t]);
    }
}

// Exclusive scan of partial[0..RADIX_THREADS) by thread 0 (a few hundred adds; simpler than a tree
// and not the bottleneck). Call from uniform control flow.
fn scan_partial(t: u32) {
    workgroupBarrier();
    if t == 0u {
        var run = 0u;
        for (var k = 0u; k < RADIX_THREADS; k++) {
            let v = partial[k];
            partial[k] = run;
            run += v;
        }
    }
    workgroupBarrier();
}

@compute @workgroup_size(RADIX_THREADS)
fn radix_scan(@builtin(local_invocation_index) t: u32) {
    let len = RADIX_BINS * blocks();
    let per = (len + RADIX_THREADS - 1u) / RADIX_THREADS;
    let start = t * per;
    var sum = 0u;
    for (var k = 0u; k < per; k++) {
        let i = start + k;
        if i < len {
            sum += hist[i];
        }
    }
    partial[t] = sum;
    scan_partial(t);
    var run = partial[t];
    for (var k = 0u; k < per; k++) {
        let i = start + k;
        if i < len {
            let v = hist[i];
            hist[i] = run;
            run += v;
        }
    }
}

@compute @workgroup_size(RADIX_THREADS)
fn radix_scatter(
    @builtin(workgroup_id) wg: vec3<u32>,
    @builtin(num_workgroups) nwg: vec3<u32>,
    @builtin(local_invocation_index) t: u32,
) {
    let block = block_index(wg, nwg);
    let mine = own_digit_counts(block, t);
    for (var d = 0u; d < RADIX_BINS; d++) {
        thread_counts[d * RADIX_THREADS + t] = mine[d];
    }
    workgroupBarrier();
    // Exclusive scan of thread_counts in (digit, thread) order: each thread scans RADIX_BINS
    // consecutive counts, then the per-thread sums are scanned and added back.
    let own = t * RADIX_BINS;
    var sum = 0u;
    for (var k = 0u; k < RADIX_BINS; k++) {
        let v = thread_counts[own + k];
        thread_counts[own + k] = sum;
        sum += v;
    }
    partial[t] = sum;
    scan_partial(t);
    for (var k = 0u; k < RADIX_BINS; k++) {
        thread_counts[own + k] += partial[t];
    }
    workgroupBarrier();
    if block >= blocks() {
        return;
    }
    // thread_counts[d * RADIX_THREADS + t] − thread_counts[d * RADIX_THREADS] entries of digit d
    // come before this thread's in the block.
    var cursor: array<u32, RADIX_BINS>;
    for (var d = 0u; d < RADIX_BINS; d++) {
        let first = d * RADIX_THREADS;
        cursor[d] = hist[d * blocks() + block] + thread_counts[first + t] - thread_counts[first];
    }
    let start = block * RADIX_BLOCK + t * RADIX_ITEMS;
    for (var k = 0u; k < RADIX_ITEMS; k++) {
        let i = start + k;
        if i < total() {
            let e = keys_in[i];
            let d = digit(e);
            keys_out[cursor[d]] = e;
            cursor[d] += 1u;
        }
    }
}
