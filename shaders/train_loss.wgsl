// The resident trainer's losses (METHOD.md §6) and their gradients down to the G-buffers and the
// Stokes images, ports of `train::step::run` and of `phygap::loss` in f32 (after
// train_common.wgsl and train_params.wgsl):
//   `compose`           the α-premultiplied prediction: albedo (plain 2DGS), S0, or the intensity
//                       behind the view's polarizer;
//   `ssim_moments_h`    SSIM's five local moments of each channel (μx, μy, E[x²], E[y²], E[xy]),
//                       blurred along rows (11-tap Gaussian, σ = 1.5, zero padding);
//   `ssim_moments_v`    ... and along columns; the SSIM map's sum and the adjoints of μx, E[x²] and
//                       E[xy] per channel (`loss::ssim`);
//   `ssim_adjoint_h`    the adjoints blurred along rows;
//   `loss_chain`        the adjoints blurred along columns, and every other term at the pixel:
//                       L1, mask MSE (weighted), the Stokes L1 or the extra L1 of partial views, edge-aware
//                       normal smoothness, depth distortion, the AoLP normal prior,
//                       depth–normal consistency (its
//                       gradients before the
//                       factor λ / valid pixels, which is known only after the reduction), and
//                       the chain from the prediction to the Stokes images, α and albedo, with the
//                       polarizer angle's gradient;
//   `reduce_losses`     one workgroup: the per-workgroup partial sums into the step status.
// Threading: one thread per pixel (train_common.wgsl); the kernels with partial sums reduce them
// across the workgroup in workgroup memory (fixed order), and every thread takes part in the
// barriers (threads past the last pixel add zeros).

@group(0) @binding(1) var<storage, read> gbuf: array<f32>;
// Per pixel 15 values: S0, S1, S2, diffuse, specular (RGB each); zero where not shaded.
@group(0) @binding(2) var<storage, read> stokes: array<f32>;
// Per pixel TARGET_FLOATS values: the photometric target (RGB), the mask, the S1 and S2 targets
// (RGB), the confidence of the pixel's polarization and its weight in the mask loss.
@group(0) @binding(3) var<storage, read> target_image: array<f32>;
const TARGET_FLOATS: u32 = 12u;
// Per pixel 3 values: the α-premultiplied prediction.
@group(0) @binding(4) var<storage, read_write> pred: array<f32>;
// Planes of P values (plane-major): SSIM's moments (15 planes) or adjoints (9 planes).
@group(0) @binding(5) var<storage, read_write> blur_a: array<f32>;
@group(0) @binding(6) var<storage, read_write> blur_b: array<f32>;
@group(0) @binding(7) var<storage, read_write> partials: array<f32>;
// Per pixel 9 values: dL/dS0, dL/dS1, dL/dS2 (RGB each), the shader's upstream.
@group(0) @binding(8) var<storage, read_write> d_stokes: array<f32>;
// Per pixel NUM_OUT values: the loss terms' gradient on α, depth, normal, albedo, roughness,
// IoR, squared depth.
@group(0) @binding(9) var<storage, read_write> up_partial: array<f32>;
// Per pixel 6 values: the depth–normal loss's gradients on the normal and the depth normal,
// before the factor λ / valid pixels.
@group(0) @binding(10) var<storage, read_write> dn_grad: array<f32>;
@group(0) @binding(11) var<storage, read_write> status: array<u32>;
@group(0) @binding(12) var<storage, read> depth_normal: array<vec4<f32>>;

const SSIM_RADIUS: i32 = 5;
const SSIM_C1: f32 = 0.0001;
const SSIM_C2: f32 = 0.0009;
const NORMAL_SMOOTH_EPS: f32 = 1e-6;
const MIN_NORMAL_NORM: f32 = 1e-12;
// `loss::POLARIZATION_MIN_S0`.
const POLARIZATION_MIN_S0: f32 = 1e-4;

var<workgroup> wg_sum: array<f32, THREADS>;

// Tap k of the SSIM window.
fn gauss(k: i32) -> f32 {
    return train.gauss[k / 4][k % 4];
}

fn pred_rgb(p: u32) -> vec3<f32> {
    return vec3<f32>(pred[3u * p], pred[3u * p + 1u], pred[3u * p + 2u]);
}

fn target_rgb(p: u32, slot: u32) -> vec3<f32> {
    let o = TARGET_FLOATS * p + slot;
    return vec3<f32>(target_image[o], target_image[o + 1u], target_image[o + 2u]);
}

fn stokes_rgb(p: u32, k: u32) -> vec3<f32> {
    let o = 15u * p + 3u * k;
    return vec3<f32>(stokes[o], stokes[o + 1u], stokes[o + 2u]);
}

fn gbuf_vec3(p: u32, first: u32) -> vec3<f32> {
    let o = NUM_OUT * p + first;
    return vec3<f32>(gbuf[o], gbuf[o + 1u], gbuf[o + 2u]);
}

// The workgroup's sum of `value` into partials[slot · groups + workgroup]. Call from uniform
// control flow.
fn workgroup_sum(t: u32, wg: u32, slot: u32, value: f32) {
    wg_sum[t] = value;
    workgroupBarrier();
    for (var half = THREADS / 2u; half > 0u; half = half >> 1u) {
        if t < half {
            wg_sum[t] += wg_sum[t + half];
        }
        workgroupBarrier();
    }
    if t == 0u {
        partials[slot * train.groups + wg] = wg_sum[0];
    }
    workgroupBarrier();
}

// The colour behind the prediction at p (not yet multiplied by α).
fn colour_at(p: u32) -> vec3<f32> {
    if train.shaded == 0u {
        return gbuf_vec3(p, 5u) * train.unpolarized_scale;
    }
    if train.has_theta == 0u {
        return stokes_rgb(p, 0u) * train.unpolarized_scale;
    }
    return 0.5 * (stokes_rgb(p, 0u) + stokes_rgb(p, 1u) * train.cos_2theta
        + stokes_rgb(p, 2u) * train.sin_2theta);
}

@compute @workgroup_size(THREADS)
fn compose(@builtin(global_invocation_id) gid: vec3<u32>, @builtin(num_workgroups) nwg: vec3<u32>) {
    let p = pixel_index(gid, nwg);
    if p >= train.pixels {
        return;
    }
    let v = colour_at(p) * gbuf[NUM_OUT * p];
    pred[3u * p] = v.x;
    pred[3u * p + 1u] = v.y;
    pred[3u * p + 2u] = v.z;
}

@compute @workgroup_size(THREADS)
fn ssim_moments_h(@builtin(global_invocation_id) gid: vec3<u32>, @builtin(num_workgroups) nwg: vec3<u32>) {
    let p = pixel_index(gid, nwg);
    let pixels = train.pixels;
    if p >= pixels {
        return;
    }
    let w = i32(train.width);
    let x = i32(p % train.width);
    let row = p - u32(x);
    var m: array<f32, 15>;
    for (var k = 0; k < 15; k++) {
        m[k] = 0.0;
    }
    for (var tap = 0; tap < 11; tap++) {
        let xi = x + tap - SSIM_RADIUS;
        if xi < 0 || xi >= w {
            continue;
        }
        let g = gauss(tap);
        let q = row + u32(xi);
        let a = pred_rgb(q);
        let b = target_rgb(q, 0u);
        for (var c = 0u; c < 3u; c++) {
            m[5u * c] += g * a[c];
            m[5u * c + 1u] += g * b[c];
            m[5u * c + 2u] += g * a[c] * a[c];
            m[5u * c + 3u] += g * b[c] * b[c];
            m[5u * c + 4u] += g * a[c] * b[c];
        }
    }
    for (var k = 0u; k < 15u; k++) {
        blur_a[k * pixels + p] = m[k];
    }
}

// Plane `plane` of blur_a blurred along columns, at pixel p.
fn column_blur_a(p: u32, plane: u32) -> f32 {
    let pixels = train.pixels;
    let w = train.width;
    let y = i32(p / w);
    var sum = 0.0;
    for (var tap = 0; tap < 11; tap++) {
        let yi = y + tap - SSIM_RADIUS;
        if yi < 0 || yi >= i32(train.height) {
            continue;
        }
        sum += gauss(tap) * blur_a[plane * pixels + u32(yi) * w + p % w];
    }
    return sum;
}

@compute @workgroup_size(THREADS)
fn ssim_moments_v(
    @builtin(global_invocation_id) gid: vec3<u32>,
    @builtin(num_workgroups) nwg: vec3<u32>,
    @builtin(workgroup_id) wg: vec3<u32>,
    @builtin(local_invocation_index) t: u32,
) {
    let p = pixel_index(gid, nwg);
    let pixels = train.pixels;
    var ssim_sum = 0.0;
    if p < pixels {
        let inv_n = 1.0 / f32(3u * pixels);
        for (var c = 0u; c < 3u; c++) {
            let mu_x = column_blur_a(p, 5u * c);
            let mu_y = column_blur_a(p, 5u * c + 1u);
            let e_xx = column_blur_a(p, 5u * c + 2u);
            let e_yy = column_blur_a(p, 5u * c + 3u);
            let e_xy = column_blur_a(p, 5u * c + 4u);
            let a = 2.0 * mu_x * mu_y + SSIM_C1;
            let b = 2.0 * (e_xy - mu_x * mu_y) + SSIM_C2;
            let cc = mu_x * mu_x + mu_y * mu_y + SSIM_C1;
            let d = (e_xx - mu_x * mu_x) + (e_yy - mu_y * mu_y) + SSIM_C2;
            let s = a * b / (cc * d);
            ssim_sum += s;
            let ds_da = b / (cc * d) * inv_n;
            let ds_db = a / (cc * d) * inv_n;
            let ds_dc = -s / cc * inv_n;
            let ds_dd = -s / d * inv_n;
            blur_b[(3u * c) * pixels + p] = 2.0 * mu_y * (ds_da - ds_db) + 2.0 * mu_x * (ds_dc - ds_dd);
            blur_b[(3u * c + 1u) * pixels + p] = ds_dd;
            blur_b[(3u * c + 2u) * pixels + p] = 2.0 * ds_db;
        }
    }
    workgroup_sum(t, workgroup_index(wg, nwg), SLOT_SSIM, ssim_sum);
}

@compute @workgroup_size(THREADS)
fn ssim_adjoint_h(@builtin(global_invocation_id) gid: vec3<u32>, @builtin(num_workgroups) nwg: vec3<u32>) {
    let p = pixel_index(gid, nwg);
    let pixels = train.pixels;
    if p >= pixels {
        return;
    }
    let w = i32(train.width);
    let x = i32(p % train.width);
    let row = p - u32(x);
    for (var k = 0u; k < 9u; k++) {
        var sum = 0.0;
        for (var tap = 0; tap < 11; tap++) {
            let xi = x + tap - SSIM_RADIUS;
            if xi >= 0 && xi < w {
                sum += gauss(tap) * blur_b[k * pixels + row + u32(xi)];
            }
        }
        blur_a[k * pixels + p] = sum;
    }
}

// −1, 0 or 1 per component (0 at equality: the L1 subgradient there).
fn sign3(v: vec3<f32>) -> vec3<f32> {
    return sign(v);
}

// Edge weight exp(−mean_c |Δ target|) between pixels a and b.
fn edge_weight(a: u32, b: u32) -> f32 {
    let d = abs(target_rgb(b, 0u) - target_rgb(a, 0u));
    return exp(-(d.x + d.y + d.z) / 3.0);
}

// The smoothed norm's pair term between pixels a and b: (weight / ‖d‖_ε, d, weight · (‖d‖_ε − √ε)).
struct SmoothPair {
    scale: f32,
    d: vec3<f32>,
    value: f32,
}

fn smooth_pair(a: u32, b: u32) -> SmoothPair {
    let weight = edge_weight(a, b);
    let d = gbuf_vec3(b, 2u) - gbuf_vec3(a, 2u);
    let norm = sqrt(dot(d, d) + NORMAL_SMOOTH_EPS);
    return SmoothPair(weight / norm, d, weight * (norm - sqrt(NORMAL_SMOOTH_EPS)));
}

@compute @workgroup_size(THREADS)
fn loss_chain(
    @builtin(global_invocation_id) gid: vec3<u32>,
    @builtin(num_workgroups) nwg: vec3<u32>,
    @builtin(workgroup_id) wg: vec3<u32>,
    @builtin(local_invocation_index) t: u32,
) {
    let p = pixel_index(gid, nwg);
    let pixels = train.pixels;
    var sums: array<f32, SLOTS>;
    for (var k = 0u; k < SLOTS; k++) {
        sums[k] = 0.0;
    }
    if p < pixels {
        let w = train.width;
        let i = p % w;
        let j = p / w;
        let inv3 = 1.0 / f32(3u * pixels);
        let inv_p = 1.0 / f32(pixels);
        let alpha = gbuf[NUM_OUT * p];
        let prediction = pred_rgb(p);
        let tgt = target_rgb(p, 0u);

        // Photometric: (1 − λ)·L1 + λ·(1 − SSIM); the SSIM adjoints blurred along columns.
        let diff = prediction - tgt;
        sums[SLOT_L1] = abs(diff.x) + abs(diff.y) + abs(diff.z);
        var ssim_grad = vec3<f32>(0.0);
        for (var c = 0u; c < 3u; c++) {
            let b0 = column_blur_a(p, 3u * c);
            let b1 = column_blur_a(p, 3u * c + 1u);
            let b2 = column_blur_a(p, 3u * c + 2u);
            ssim_grad[c] = b0 + 2.0 * prediction[c] * b1 + tgt[c] * b2;
        }
        let lambda_ssim = train.lambda_ssim;
        var gp = (1.0 - lambda_ssim) * sign3(diff) * inv3 - lambda_ssim * ssim_grad;
        // The extra L1 on Î(θ) of partial views.
        gp += train.lambda_extra_l1 * sign3(diff) * inv3;

        var up: array<f32, NUM_OUT>;
        for (var k = 0u; k < NUM_OUT; k++) {
            up[k] = 0.0;
        }
        // Mask.
        let m = target_image[TARGET_FLOATS * p + 3u];
        let mask_weight = target_image[TARGET_FLOATS * p + 11u];
        sums[SLOT_MASK] = mask_weight * (alpha - m) * (alpha - m);
        up[0] += train.lambda_mask * 2.0 * mask_weight * (alpha - m) * inv_p;

        // From the prediction to the Stokes images (or the albedo) and α.
        var d0 = vec3<f32>(0.0);
        var d1 = vec3<f32>(0.0);
        var d2 = vec3<f32>(0.0);
        let k = train.unpolarized_scale;
        if train.shaded == 0u {
            let albedo = gbuf_vec3(p, 5u);
            let g_albedo = gp * (k * alpha);
            up[5] += g_albedo.x;
            up[6] += g_albedo.y;
            up[7] += g_albedo.z;
            up[0] += k * dot(albedo, gp);
        } else {
            let s0 = stokes_rgb(p, 0u);
            let s1 = stokes_rgb(p, 1u);
            let s2 = stokes_rgb(p, 2u);
            if train.has_theta == 0u {
                d0 = gp * (alpha * k);
                up[0] += k * dot(s0, gp);
            } else {
                let c2 = train.cos_2theta;
                let s2t = train.sin_2theta;
                d0 = gp * (0.5 * alpha);
                d1 = gp * (0.5 * alpha * c2);
                d2 = gp * (0.5 * alpha * s2t);
                up[0] += dot(0.5 * (s0 + s1 * c2 + s2 * s2t), gp);
                sums[SLOT_ANGLE] = alpha * dot(s2 * c2 - s1 * s2t, gp);
            }
            if train.stokes_loss != 0u {
                let r1 = alpha * s1 - target_rgb(p, 4u);
                let r2 = alpha * s2 - target_rgb(p, 7u);
                let a1 = abs(r1);
                let a2 = abs(r2);
                sums[SLOT_STOKES] = a1.x + a1.y + a1.z + a2.x + a2.y + a2.z;
                let g1 = train.lambda_stokes * sign3(r1) * inv3;
                let g2 = train.lambda_stokes * sign3(r2) * inv3;
                d1 += g1 * alpha;
                d2 += g2 * alpha;
                up[0] += dot(s1, g1) + dot(s2, g2);
            }
        }
        for (var c = 0u; c < 3u; c++) {
            d_stokes[9u * p + c] = d0[c];
            d_stokes[9u * p + 3u + c] = d1[c];
            d_stokes[9u * p + 6u + c] = d2[c];
        }

        // Edge-aware normal smoothness: this pixel's pairs with its right and lower neighbours
        // (value and both ends' gradients), and its upper and left neighbours' pairs with it.
        let lambda_smooth = train.lambda_normal_smooth;
        if lambda_smooth > 0.0 {
            var g = vec3<f32>(0.0);
            if i + 1u < w {
                let pair = smooth_pair(p, p + 1u);
                sums[SLOT_SMOOTH] += pair.value;
                g -= pair.scale * pair.d;
            }
            if j + 1u < train.height {
                let pair = smooth_pair(p, p + w);
                sums[SLOT_SMOOTH] += pair.value;
                g -= pair.scale * pair.d;
            }
            if i >= 1u {
                let pair = smooth_pair(p - 1u, p);
                g += pair.scale * pair.d;
            }
            if j >= 1u {
                let pair = smooth_pair(p - w, p);
                g += pair.scale * pair.d;
            }
            let scaled = lambda_smooth * inv_p * g;
            up[2] += scaled.x;
            up[3] += scaled.y;
            up[4] += scaled.z;
        }

        // Depth–normal consistency, before the factor λ / (valid pixels).
        var gn = vec3<f32>(0.0);
        var gd = vec3<f32>(0.0);
        if train.lambda_depth_normal > 0.0 {
            let n = gbuf_vec3(p, 2u);
            let nd = depth_normal[p].xyz;
            let len = length(n);
            if len > MIN_NORMAL_NORM && length(nd) > MIN_NORMAL_NORM {
                let unit = n / len;
                let cosine = dot(unit, nd);
                sums[SLOT_DEPTH_NORMAL] = 1.0 - cosine;
                sums[SLOT_DEPTH_NORMAL_COUNT] = 1.0;
                gn = -(nd - unit * cosine) / len;
                gd = -unit;
            }
        }
        for (var c = 0u; c < 3u; c++) {
            dn_grad[6u * p + c] = gn[c];
            dn_grad[6u * p + 3u + c] = gd[c];
        }
        // Depth distortion α² (E[z²] − E[z]²), weighted by λ / (pixels · radius²).
        let lambda_distortion = train.lambda_distortion;
        if lambda_distortion > 0.0 {
            let z = gbuf[NUM_OUT * p + 1u];
            let spread = gbuf[NUM_OUT * p + 10u] - z * z;
            sums[SLOT_DISTORTION] = alpha * alpha * spread;
            let scale = lambda_distortion * inv_p;
            up[0] += 2.0 * alpha * spread * scale;
            up[1] -= 2.0 * alpha * alpha * z * scale;
            up[10] += alpha * alpha * scale;
        }
        // The AoLP prior DoLP² sin² 2(ψ − φ) on the object's pixels (`loss::aolp_normal`):
        // φ is the rendered normal's azimuth in the pixel's Stokes frame, ψ and the DoLP are
        // measured (channel means of the targets, the DoLP times the pixel's confidence);
        // weighted by λ / pixels.
        let lambda_aolp = train.lambda_aolp;
        if lambda_aolp > 0.0 && m >= 0.5 {
            let s0 = max((tgt.x + tgt.y + tgt.z) / 3.0, POLARIZATION_MIN_S0);
            let t1 = target_rgb(p, 4u);
            let t2 = target_rgb(p, 7u);
            var c = (t1.x + t1.y + t1.z) / 3.0 / s0;
            var s = (t2.x + t2.y + t2.z) / 3.0 / s0;
            let dolp = sqrt(c * c + s * s);
            if dolp > 1.0 {
                c /= dolp;
                s /= dolp;
            }
            let confidence = target_image[TARGET_FLOATS * p + 10u];
            c *= confidence;
            s *= confidence;
            let d = normalize(to_world(camera_dir(p)));
            // The Stokes frame of `camera::stokes_frame`; the camera's up is −(OpenCV down).
            let frame_x = normalize(cross(d, -train.rot1.xyz));
            let frame_y = cross(frame_x, d);
            let n = gbuf_vec3(p, 2u);
            let a = dot(n, frame_x);
            let b = dot(n, frame_y);
            let q = a * a + b * b;
            if (c != 0.0 || s != 0.0) && q >= 1e-24 {
                let r = (s * (a * a - b * b) - 2.0 * c * a * b) / q;
                sums[SLOT_AOLP] = r * r;
                let dr_da = (2.0 * s * a - 2.0 * c * b - 2.0 * r * a) / q;
                let dr_db = (-2.0 * s * b - 2.0 * c * a - 2.0 * r * b) / q;
                let g = (frame_x * dr_da + frame_y * dr_db) * (2.0 * r * lambda_aolp * inv_p);
                up[2] += g.x;
                up[3] += g.y;
                up[4] += g.z;
            }
        }
        for (var c = 0u; c < NUM_OUT; c++) {
            up_partial[NUM_OUT * p + c] = up[c];
        }
    }
    let group = workgroup_index(wg, nwg);
    for (var slot = 0u; slot < SLOTS; slot++) {
        if slot != SLOT_SSIM {
            workgroup_sum(t, group, slot, sums[slot]);
        }
    }
}

@compute @workgroup_size(THREADS)
fn reduce_losses(@builtin(local_invocation_index) t: u32) {
    let groups = train.groups;
    for (var slot = 0u; slot < SLOTS; slot++) {
        var sum = 0.0;
        for (var g = t; g < groups; g += THREADS) {
            sum += partials[slot * groups + g];
        }
        wg_sum[t] = sum;
        workgroupBarrier();
        for (var half = THREADS / 2u; half > 0u; half = half >> 1u) {
            if t < half {
                wg_sum[t] += wg_sum[t + half];
            }
            workgroupBarrier();
        }
        if t == 0u {
            status[SUM_FIRST + slot] = bitcast<u32>(wg_sum[0]);
        }
        workgroupBarrier();
    }
}
