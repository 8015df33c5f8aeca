//! The table of the device kernels: for each compute pipeline, its entry point, the `shaders/`
//! files concatenated (in order) into its WGSL module, and the bindings of its bind group (group
//! 0). This table is the only place on the Rust side that says either:
//!
//! - [`super::device::Device::kernel`] compiles a [`KernelSpec`] with a bind group layout built
//!   from its bindings (not derived from the WGSL), and [`super::device::Device::bind`] binds
//!   buffers by their WGSL names, looking their numbers up here; no call site holds a binding
//!   number. Renumbering a binding is one edit in its WGSL file and one here.
//! - The tests below compose every kernel under every [`Variant`], parse and validate it with
//!   naga, and check that the WGSL globals its entry point uses are exactly its bindings here
//!   (name, number, uniform / read-only storage / read-write storage), and that every file of
//!   `shaders/` goes into some kernel. A binding swapped, retyped or forgotten on either side
//!   fails there, before any device runs it.
//!
//! Two parts of a composition depend on the adapter ([`Variant`]): `add_grad`, float atomics or
//! a compare-and-swap loop ([`AtomicsMode`]), and `walk_length`, with subgroups or without
//! ([`Walk`]). Both choices bind the same buffers.
//!
//! Threading: a constant table; what each kernel's threads do is in its WGSL file.

/// How the backward passes add into per-surfel and per-texel gradient sums.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum AtomicsMode {
    /// Native `atomicAdd` on `atomic<f32>` (`SHADER_FLOAT32_ATOMIC`).
    Float,
    /// Compare-and-swap loop on the f32 bit pattern in an `atomic<u32>`.
    CompareExchange,
}

/// How far back each thread of the rasterizer's backward pass walks its tile's list.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Walk {
    /// From its own last composited entry.
    OwnEntries,
    /// From the last entry any thread of its subgroup composited, in step with them (`SUBGROUP`).
    Subgroup,
}

/// The sources an adapter's features choose.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) struct Variant {
    pub(super) atomics: AtomicsMode,
    pub(super) walk: Walk,
}

impl Variant {
    /// Every variant, for the tests.
    #[cfg(test)]
    pub(super) const ALL: [Variant; 4] = [
        Variant {
            atomics: AtomicsMode::Float,
            walk: Walk::OwnEntries,
        },
        Variant {
            atomics: AtomicsMode::Float,
            walk: Walk::Subgroup,
        },
        Variant {
            atomics: AtomicsMode::CompareExchange,
            walk: Walk::OwnEntries,
        },
        Variant {
            atomics: AtomicsMode::CompareExchange,
            walk: Walk::Subgroup,
        },
    ];
}

/// One piece of a kernel's WGSL module.
#[derive(Clone, Copy, Debug)]
pub(super) enum Part {
    /// A file of `shaders/`: its name and text.
    File(&'static str, &'static str),
    /// `add_grad` and its `grad_acc` binding: `atomic_float.wgsl` or `atomic_cas.wgsl`.
    AddGrad,
    /// `walk_length`: `walk_own.wgsl` or `walk_subgroup.wgsl`.
    WalkLength,
}

impl Part {
    /// The file this part is under `variant`: its name and text.
    pub(super) fn file(self, variant: Variant) -> (&'static str, &'static str) {
        let part = match (self, variant.atomics, variant.walk) {
            (Part::AddGrad, AtomicsMode::Float, _) => file::ATOMIC_FLOAT,
            (Part::AddGrad, AtomicsMode::CompareExchange, _) => file::ATOMIC_CAS,
            (Part::WalkLength, _, Walk::OwnEntries) => file::WALK_OWN,
            (Part::WalkLength, _, Walk::Subgroup) => file::WALK_SUBGROUP,
            (own @ Part::File(..), _, _) => own,
        };
        match part {
            Part::File(name, text) => (name, text),
            Part::AddGrad | Part::WalkLength => unreachable!("resolved above"),
        }
    }
}

/// How a kernel uses one of its buffers.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub(super) enum Access {
    /// `var<uniform>`.
    Uniform,
    /// `var<storage, read>`.
    Read,
    /// `var<storage, read_write>`.
    ReadWrite,
}

/// One binding of group 0: the WGSL variable's name, its `@binding` number and its access.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) struct Binding {
    pub(super) name: &'static str,
    pub(super) number: u32,
    pub(super) access: Access,
}

const fn uniform(number: u32, name: &'static str) -> Binding {
    Binding {
        name,
        number,
        access: Access::Uniform,
    }
}

const fn read(number: u32, name: &'static str) -> Binding {
    Binding {
        name,
        number,
        access: Access::Read,
    }
}

const fn read_write(number: u32, name: &'static str) -> Binding {
    Binding {
        name,
        number,
        access: Access::ReadWrite,
    }
}

impl Binding {
    /// The entry of a bind group layout (compute stage) that this binding needs.
    pub(super) fn layout_entry(&self) -> wgpu::BindGroupLayoutEntry {
        let ty = match self.access {
            Access::Uniform => wgpu::BufferBindingType::Uniform,
            Access::Read => wgpu::BufferBindingType::Storage { read_only: true },
            Access::ReadWrite => wgpu::BufferBindingType::Storage { read_only: false },
        };
        wgpu::BindGroupLayoutEntry {
            binding: self.number,
            visibility: wgpu::ShaderStages::COMPUTE,
            ty: wgpu::BindingType::Buffer {
                ty,
                has_dynamic_offset: false,
                min_binding_size: None,
            },
            count: None,
        }
    }
}

/// One compute pipeline: its name (the pipeline's label), entry point, the parts of its module
/// in order, and its bindings (in groups that kernels share).
#[derive(Debug)]
pub(super) struct KernelSpec {
    pub(super) name: &'static str,
    pub(super) entry: &'static str,
    pub(super) parts: &'static [Part],
    pub(super) bindings: &'static [&'static [Binding]],
}

impl KernelSpec {
    /// The files of the module under `variant`, in order: (name, text).
    pub(super) fn files(
        &self,
        variant: Variant,
    ) -> impl Iterator<Item = (&'static str, &'static str)> + '_ {
        self.parts.iter().map(move |p| p.file(variant))
    }

    /// The WGSL module under `variant`.
    pub(super) fn source(&self, variant: Variant) -> String {
        self.files(variant).map(|(_, text)| text).collect()
    }

    /// Every binding.
    pub(super) fn all_bindings(&self) -> impl Iterator<Item = &'static Binding> {
        self.bindings.iter().flat_map(|group| group.iter())
    }

    /// The number of the binding named `name`.
    ///
    /// # Panics
    /// When the kernel has no such binding (a call site names a buffer the table does not).
    pub(super) fn number_of(&self, name: &str) -> u32 {
        self.all_bindings()
            .find(|b| b.name == name)
            .unwrap_or_else(|| panic!("kernel `{}` has no binding `{name}`", self.name))
            .number
    }
}

/// The files of `shaders/`.
mod file {
    use super::Part;

    macro_rules! shader_files {
        ($($id:ident = $name:literal;)*) => {
            $(pub(in crate::gpu) const $id: Part =
                Part::File($name, include_str!(concat!("../../shaders/", $name)));)*
            /// Every file, for the tests.
            #[cfg(test)]
            pub(in crate::gpu) const ALL: &[Part] = &[$($id),*];
        };
    }

    shader_files! {
        ATOMIC_CAS = "atomic_cas.wgsl";
        ATOMIC_FLOAT = "atomic_float.wgsl";
        BIN = "bin.wgsl";
        COMMON = "common.wgsl";
        LIGHT_GLOBAL = "light_global.wgsl";
        LIGHT_GLOBAL_BACKWARD = "light_global_backward.wgsl";
        LIGHT_GRIDMAP = "light_gridmap.wgsl";
        LIGHT_GRIDMAP_BACKWARD = "light_gridmap_backward.wgsl";
        PREFILTER = "prefilter.wgsl";
        PROJECT = "project.wgsl";
        PROJECT_BACKWARD = "project_backward.wgsl";
        RADIX_SORT = "radix_sort.wgsl";
        RASTERIZE = "rasterize.wgsl";
        RASTERIZE_BACKWARD = "rasterize_backward.wgsl";
        SCAN = "scan.wgsl";
        SHADE = "shade.wgsl";
        SHADE_BACKWARD = "shade_backward.wgsl";
        SHADE_COMMON = "shade_common.wgsl";
        TILE_LIST = "tile_list.wgsl";
        TRAIN_COMMON = "train_common.wgsl";
        TRAIN_LOSS = "train_loss.wgsl";
        TRAIN_PARAMS = "train_params.wgsl";
        TRAIN_PIXELS = "train_pixels.wgsl";
        TRAIN_UPDATE = "train_update.wgsl";
        TSDF_FUSE = "tsdf_fuse.wgsl";
        WALK_OWN = "walk_own.wgsl";
        WALK_SUBGROUP = "walk_subgroup.wgsl";
    }
}

use Part::{AddGrad, WalkLength};

/// The bindings of tile_list.wgsl: the band's parameters, sorted tile lists and projections.
const TILE_LISTS: &[Binding] = &[
    uniform(0, "params"),
    read(1, "entries"),
    read(2, "ranges"),
    read(3, "proj"),
];

/// `grad_acc` of atomic_float.wgsl / atomic_cas.wgsl.
const GRAD_SUMS: &[Binding] = &[read_write(8, "grad_acc")];

/// The bindings of shade_common.wgsl: the parameters, the global light and the BRDF table, and
/// the pixels' inputs.
const SHADE_INPUTS: &[Binding] = &[
    uniform(0, "params"),
    read(1, "light"),
    read(2, "tables"),
    read(3, "pixels"),
    read(4, "active_pixels"),
];

/// The bindings of light_gridmap.wgsl: GridMap's probes, anchors and BVH.
const PROBES: &[Binding] = &[
    read(9, "probes"),
    read(10, "anchors"),
    read(11, "bvh_nodes"),
    read(12, "bvh_slots"),
    read(13, "bvh_links"),
];

/// Declares each kernel as a constant, and the list of them all for the tests.
macro_rules! kernel_table {
    ($($(#[$meta:meta])* $id:ident = $spec:expr;)*) => {
        $($(#[$meta])* pub(super) const $id: KernelSpec = $spec;)*
        /// Every kernel of the table.
        #[cfg(test)]
        pub(super) const KERNELS: &[&KernelSpec] = &[$(&$id),*];
    };
}

kernel_table! {
    // The rasterizer (`super::raster`, and the resident trainer's steps).

    /// Projection and culling, and the tile count of each surfel.
    PROJECT = KernelSpec {
        name: "project",
        entry: "project",
        parts: &[file::COMMON, file::PROJECT],
        bindings: &[&[
            uniform(0, "params"),
            read(1, "raw"),
            read_write(2, "proj"),
            read_write(3, "tile_counts"),
        ]],
    };
    /// The (tile, depth, surfel) entries of each surfel, at its scanned offset.
    EMIT = KernelSpec {
        name: "emit",
        entry: "emit",
        parts: &[file::COMMON, file::BIN],
        bindings: &[&[
            uniform(0, "params"),
            read(1, "proj"),
            read(2, "offsets"),
            read_write(3, "entries"),
        ]],
    };
    /// Where each tile's run of sorted entries starts and ends.
    TILE_RANGES = KernelSpec {
        name: "tile_ranges",
        entry: "tile_ranges",
        parts: &[file::COMMON, file::BIN],
        bindings: &[&[
            read_write(3, "entries"),
            read_write(4, "ranges"),
            read(5, "entry_count"),
        ]],
    };
    /// A radix pass's digit counts per block.
    RADIX_COUNT = KernelSpec {
        name: "radix_count",
        entry: "radix_count",
        parts: &[file::RADIX_SORT],
        bindings: &[&[
            uniform(0, "pass_"),
            read(1, "keys_in"),
            read_write(3, "hist"),
            read(4, "sort_count"),
        ]],
    };
    /// A radix pass's scan of the digit counts.
    RADIX_SCAN = KernelSpec {
        name: "radix_scan",
        entry: "radix_scan",
        parts: &[file::RADIX_SORT],
        bindings: &[&[read_write(3, "hist"), read(4, "sort_count")]],
    };
    /// A radix pass's stable scatter.
    RADIX_SCATTER = KernelSpec {
        name: "radix_scatter",
        entry: "radix_scatter",
        parts: &[file::RADIX_SORT],
        bindings: &[&[
            uniform(0, "pass_"),
            read(1, "keys_in"),
            read_write(2, "keys_out"),
            read_write(3, "hist"),
            read(4, "sort_count"),
        ]],
    };
    /// Forward compositing into the G-buffers.
    RASTERIZE = KernelSpec {
        name: "rasterize",
        entry: "rasterize",
        parts: &[file::COMMON, file::TILE_LIST, file::RASTERIZE],
        bindings: &[
            TILE_LISTS,
            &[
                read_write(4, "gbuf"),
                read_write(5, "final_t"),
                read_write(6, "contrib"),
                read_write(7, "evals"),
            ],
        ],
    };
    /// The compositing's backward pass into the per-surfel sums.
    RASTERIZE_BACKWARD = KernelSpec {
        name: "rasterize_backward",
        entry: "rasterize_backward",
        parts: &[file::COMMON, file::TILE_LIST, file::RASTERIZE_BACKWARD, AddGrad, WalkLength],
        bindings: &[
            TILE_LISTS,
            &[
                read(4, "gbuf"),
                read(5, "upstream"),
                read(6, "final_t"),
                read(7, "contrib"),
            ],
            GRAD_SUMS,
        ],
    };
    /// The per-surfel sums chained to the raw parameters.
    PROJECT_BACKWARD = KernelSpec {
        name: "project_backward",
        entry: "project_backward",
        parts: &[file::COMMON, file::PROJECT_BACKWARD],
        bindings: &[&[
            uniform(0, "params"),
            read(1, "raw"),
            read(2, "proj"),
            read(3, "grad_acc"),
            read_write(4, "raw_grads"),
        ]],
    };

    // PolarDR shading (`super::shade`), per kind of light.

    /// Shading under the global light.
    SHADE_GLOBAL = KernelSpec {
        name: "shade (global light)",
        entry: "shade",
        parts: &[file::SHADE_COMMON, file::LIGHT_GLOBAL, file::SHADE],
        bindings: &[SHADE_INPUTS, &[read_write(5, "stokes")]],
    };
    /// Shading under GridMap.
    SHADE_GRIDMAP = KernelSpec {
        name: "shade (GridMap)",
        entry: "shade",
        parts: &[file::SHADE_COMMON, file::LIGHT_GRIDMAP, file::SHADE],
        bindings: &[SHADE_INPUTS, &[read_write(5, "stokes")], PROBES],
    };
    /// Shading's backward pass under the global light.
    SHADE_BACKWARD_GLOBAL = KernelSpec {
        name: "shade_backward (global light)",
        entry: "shade_backward",
        parts: &[
            file::SHADE_COMMON,
            file::LIGHT_GLOBAL,
            file::SHADE_BACKWARD,
            file::LIGHT_GLOBAL_BACKWARD,
            AddGrad,
        ],
        bindings: &[
            SHADE_INPUTS,
            &[read(5, "upstream"), read_write(6, "pixel_grads")],
            GRAD_SUMS,
        ],
    };
    /// Shading's backward pass under GridMap.
    SHADE_BACKWARD_GRIDMAP = KernelSpec {
        name: "shade_backward (GridMap)",
        entry: "shade_backward",
        parts: &[
            file::SHADE_COMMON,
            file::LIGHT_GRIDMAP,
            file::SHADE_BACKWARD,
            file::LIGHT_GRIDMAP_BACKWARD,
            AddGrad,
        ],
        bindings: &[
            SHADE_INPUTS,
            &[read(5, "upstream"), read_write(6, "pixel_grads")],
            GRAD_SUMS,
            PROBES,
        ],
    };

    // The resident trainer's own kernels (`super::train`).

    /// The scan of each block of tile counts.
    SCAN_BLOCKS = KernelSpec {
        name: "scan_blocks",
        entry: "scan_blocks",
        parts: &[file::SCAN],
        bindings: &[&[
            uniform(0, "scan"),
            read(1, "counts"),
            read_write(2, "offsets"),
            read_write(3, "block_sums"),
        ]],
    };
    /// The scan of the block sums, the entry total and the indirect dispatch sizes.
    SCAN_SUMS = KernelSpec {
        name: "scan_sums",
        entry: "scan_sums",
        parts: &[file::SCAN],
        bindings: &[&[
            uniform(0, "scan"),
            read_write(3, "block_sums"),
            read_write(4, "status"),
            read_write(5, "dispatch"),
        ]],
    };
    /// Each block's offset added to its counts' offsets.
    SCAN_ADD = KernelSpec {
        name: "scan_add",
        entry: "scan_add",
        parts: &[file::SCAN],
        bindings: &[&[
            uniform(0, "scan"),
            read_write(2, "offsets"),
            read_write(3, "block_sums"),
        ]],
    };
    /// The shader's inputs and the depth-derived normals.
    PREPARE_PIXELS = KernelSpec {
        name: "prepare_pixels",
        entry: "prepare_pixels",
        parts: &[file::TRAIN_COMMON, file::TRAIN_PARAMS, file::TRAIN_PIXELS],
        bindings: &[&[
            uniform(0, "train"),
            read(1, "gbuf"),
            read_write(2, "shade_in"),
            read_write(3, "active_pixels"),
            read_write(4, "depth_normal"),
        ]],
    };
    /// The depth-derived normal's backward pass.
    DEPTH_NORMAL_BACKWARD = KernelSpec {
        name: "depth_normal_backward",
        entry: "depth_normal_backward",
        parts: &[file::TRAIN_COMMON, file::TRAIN_PARAMS, file::TRAIN_PIXELS],
        bindings: &[&[
            uniform(0, "train"),
            read(1, "gbuf"),
            read(5, "dn_grad"),
            read(6, "status"),
            read_write(7, "gdxy"),
        ]],
    };
    /// The upstream gradient of every G-buffer.
    ASSEMBLE_UPSTREAM = KernelSpec {
        name: "assemble_upstream",
        entry: "assemble_upstream",
        parts: &[file::TRAIN_COMMON, file::TRAIN_PARAMS, file::TRAIN_PIXELS],
        bindings: &[&[
            uniform(0, "train"),
            read_write(3, "active_pixels"),
            read(5, "dn_grad"),
            read(6, "status"),
            read_write(7, "gdxy"),
            read(8, "up_partial"),
            read(9, "shade_grads"),
            read_write(10, "upstream"),
        ]],
    };
    /// The prediction (Î(θ) or the plain colour).
    COMPOSE = KernelSpec {
        name: "compose",
        entry: "compose",
        parts: &[file::TRAIN_COMMON, file::TRAIN_PARAMS, file::TRAIN_LOSS],
        bindings: &[&[
            uniform(0, "train"),
            read(1, "gbuf"),
            read(2, "stokes"),
            read_write(4, "pred"),
        ]],
    };
    /// SSIM's moments, horizontal blur.
    SSIM_MOMENTS_H = KernelSpec {
        name: "ssim_moments_h",
        entry: "ssim_moments_h",
        parts: &[file::TRAIN_COMMON, file::TRAIN_PARAMS, file::TRAIN_LOSS],
        bindings: &[&[
            uniform(0, "train"),
            read(3, "target_image"),
            read_write(4, "pred"),
            read_write(5, "blur_a"),
        ]],
    };
    /// SSIM's moments, vertical blur, and SSIM's partial sums.
    SSIM_MOMENTS_V = KernelSpec {
        name: "ssim_moments_v",
        entry: "ssim_moments_v",
        parts: &[file::TRAIN_COMMON, file::TRAIN_PARAMS, file::TRAIN_LOSS],
        bindings: &[&[
            uniform(0, "train"),
            read_write(5, "blur_a"),
            read_write(6, "blur_b"),
            read_write(7, "partials"),
        ]],
    };
    /// SSIM's adjoint, horizontal blur.
    SSIM_ADJOINT_H = KernelSpec {
        name: "ssim_adjoint_h",
        entry: "ssim_adjoint_h",
        parts: &[file::TRAIN_COMMON, file::TRAIN_PARAMS, file::TRAIN_LOSS],
        bindings: &[&[
            uniform(0, "train"),
            read_write(5, "blur_a"),
            read_write(6, "blur_b"),
        ]],
    };
    /// Every other loss term with its gradient.
    LOSS_CHAIN = KernelSpec {
        name: "loss_chain",
        entry: "loss_chain",
        parts: &[file::TRAIN_COMMON, file::TRAIN_PARAMS, file::TRAIN_LOSS],
        bindings: &[&[
            uniform(0, "train"),
            read(1, "gbuf"),
            read(2, "stokes"),
            read(3, "target_image"),
            read_write(4, "pred"),
            read_write(5, "blur_a"),
            read_write(7, "partials"),
            read_write(8, "d_stokes"),
            read_write(9, "up_partial"),
            read_write(10, "dn_grad"),
            read(12, "depth_normal"),
        ]],
    };
    /// The partial sums reduced into the step status.
    REDUCE_LOSSES = KernelSpec {
        name: "reduce_losses",
        entry: "reduce_losses",
        parts: &[file::TRAIN_COMMON, file::TRAIN_PARAMS, file::TRAIN_LOSS],
        bindings: &[&[
            uniform(0, "train"),
            read_write(7, "partials"),
            read_write(11, "status"),
        ]],
    };
    /// Adam and the densification statistics.
    ADAM = KernelSpec {
        name: "adam",
        entry: "adam",
        parts: &[file::TRAIN_COMMON, file::TRAIN_UPDATE],
        bindings: &[&[
            uniform(0, "adam_params"),
            read_write(1, "raw"),
            read_write(2, "moment1"),
            read_write(3, "moment2"),
            read(4, "raw_grad"),
            read_write(5, "grad_sum"),
            read_write(6, "seen"),
            read_write(7, "step_status"),
        ]],
    };
    /// The step's light gradient added into the sums of the next environment update.
    ACCUMULATE_LIGHT = KernelSpec {
        name: "accumulate_light",
        entry: "accumulate_light",
        parts: &[file::TRAIN_COMMON, file::TRAIN_UPDATE],
        bindings: &[&[
            read_write(7, "step_status"),
            read(8, "light_step"),
            read_write(9, "light_pending"),
        ]],
    };

    // TSDF fusion of rendered depth (`super::tsdf`).

    /// One band of a view's G-buffers into the view's cleaned depth map.
    PREPARE_DEPTH = KernelSpec {
        name: "prepare_depth",
        entry: "prepare_depth",
        parts: &[file::COMMON, file::TSDF_FUSE],
        bindings: &[&[
            uniform(4, "depth_band"),
            read(5, "band_gbuf"),
            read_write(6, "clean_depth"),
        ]],
    };
    /// One view's votes added into every voxel's sum and count.
    FUSE_VIEW = KernelSpec {
        name: "fuse_view",
        entry: "fuse_view",
        parts: &[file::COMMON, file::TSDF_FUSE],
        bindings: &[&[
            uniform(0, "fuse"),
            read(1, "view_depth"),
            read_write(2, "tsdf_sum"),
            read_write(3, "tsdf_count"),
        ]],
    };

    // The environment prefilter (`super::prefilter`).

    /// One convolution of the plan, forward or transposed.
    CONVOLVE = KernelSpec {
        name: "convolve",
        entry: "convolve",
        parts: &[file::PREFILTER],
        bindings: &[&[
            uniform(0, "conv"),
            read(1, "dirs"),
            read(2, "solid_angle"),
            read(3, "blocks"),
            read(4, "block_texels"),
            read(5, "block_dirs"),
            read(6, "thresholds"),
            read(7, "normalizers"),
            read(8, "src"),
            read_write(9, "dst"),
            read(14, "block_starts"),
        ]],
    };
    /// The radiance of the raw base texels and its derivative.
    ACTIVATE = KernelSpec {
        name: "activate",
        entry: "activate",
        parts: &[file::PREFILTER],
        bindings: &[&[
            read(11, "raw"),
            read_write(12, "pyramid"),
            read_write(13, "derivative"),
        ]],
    };
    /// A pyramid level from the one above.
    DOWNSAMPLE = KernelSpec {
        name: "downsample",
        entry: "downsample",
        parts: &[file::PREFILTER],
        bindings: &[&[uniform(10, "level"), read_write(12, "pyramid")]],
    };
    /// A pyramid level's gradient added into the level above.
    PYRAMID_TRANSPOSE = KernelSpec {
        name: "pyramid_transpose",
        entry: "pyramid_transpose",
        parts: &[file::PREFILTER],
        bindings: &[&[uniform(10, "level"), read_write(12, "pyramid")]],
    };
    /// The base level's gradient times the activation's derivative.
    RAW_GRADIENT = KernelSpec {
        name: "raw_gradient",
        entry: "raw_gradient",
        parts: &[file::PREFILTER],
        bindings: &[&[
            read_write(9, "dst"),
            read_write(12, "pyramid"),
            read_write(13, "derivative"),
        ]],
    };
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::collections::BTreeSet;

    /// `spec` under `variant`, parsed and validated as a device would (every capability the
    /// kernels may use: float atomics, subgroups).
    fn module(spec: &KernelSpec, variant: Variant) -> (naga::Module, naga::valid::ModuleInfo) {
        let source = spec.source(variant);
        let files: Vec<&str> = spec.files(variant).map(|(name, _)| name).collect();
        let module = naga::front::wgsl::parse_str(&source).unwrap_or_else(|e| {
            panic!(
                "kernel `{}` ({files:?}) does not parse:\n{}",
                spec.name,
                e.emit_to_string(&source)
            )
        });
        let info = naga::valid::Validator::new(
            naga::valid::ValidationFlags::all(),
            naga::valid::Capabilities::all(),
        )
        .subgroup_stages(naga::valid::ShaderStages::COMPUTE)
        .subgroup_operations(naga::valid::SubgroupOperationSet::all())
        .validate(&module)
        .unwrap_or_else(|e| {
            panic!(
                "kernel `{}` ({files:?}) does not validate:\n{}",
                spec.name,
                e.emit_to_string(&source)
            )
        });
        (module, info)
    }

    /// The bindings the entry point of `spec` uses, as naga reflects them (what wgpu would derive
    /// for an automatic layout).
    fn reflected_bindings(spec: &KernelSpec, variant: Variant) -> BTreeSet<(u32, String, Access)> {
        let (module, info) = module(spec, variant);
        let (index, _) = module
            .entry_points
            .iter()
            .enumerate()
            .find(|(_, ep)| ep.name == spec.entry && ep.stage == naga::ShaderStage::Compute)
            .unwrap_or_else(|| {
                panic!(
                    "kernel `{}`: no compute entry point `{}`",
                    spec.name, spec.entry
                )
            });
        let uses = info.get_entry_point(index);
        module
            .global_variables
            .iter()
            .filter(|(handle, _)| !uses[*handle].is_empty())
            .filter_map(|(_, var)| {
                let binding = var.binding.as_ref()?;
                assert_eq!(
                    binding.group, 0,
                    "kernel `{}`: a group other than 0",
                    spec.name
                );
                let access = match var.space {
                    naga::AddressSpace::Uniform => Access::Uniform,
                    naga::AddressSpace::Storage { access }
                        if access == naga::StorageAccess::LOAD =>
                    {
                        Access::Read
                    }
                    naga::AddressSpace::Storage { .. } => Access::ReadWrite,
                    other => panic!("kernel `{}`: unexpected binding space {other:?}", spec.name),
                };
                Some((
                    binding.binding,
                    var.name.clone().unwrap_or_default(),
                    access,
                ))
            })
            .collect()
    }

    /// The variants under which `spec` is composed differently: one for a kernel without
    /// parts that depend on the adapter.
    fn distinct_variants(spec: &KernelSpec) -> Vec<Variant> {
        let mut seen: Vec<Vec<&str>> = Vec::new();
        Variant::ALL
            .into_iter()
            .filter(|&v| {
                let files: Vec<&str> = spec.files(v).map(|(name, _)| name).collect();
                let new = !seen.contains(&files);
                seen.push(files);
                new
            })
            .collect()
    }

    #[test]
    fn every_kernel_parses_and_validates_under_every_variant() {
        for spec in KERNELS {
            for variant in distinct_variants(spec) {
                module(spec, variant);
            }
        }
    }

    /// The table's bindings of each kernel are exactly the WGSL globals its entry point uses:
    /// same names, numbers and access, none missing and none extra.
    #[test]
    fn every_kernels_bindings_match_its_wgsl() {
        let mut failures = Vec::new();
        for spec in KERNELS {
            let table: BTreeSet<(u32, String, Access)> = spec
                .all_bindings()
                .map(|b| (b.number, b.name.to_owned(), b.access))
                .collect();
            assert_eq!(
                table.len(),
                spec.all_bindings().count(),
                "kernel `{}` lists a binding twice",
                spec.name
            );
            for variant in distinct_variants(spec) {
                let wgsl = reflected_bindings(spec, variant);
                if wgsl != table {
                    failures.push(format!(
                        "kernel `{}` under {variant:?}:\n  only in the table: {:?}\n  only in the \
                         WGSL: {:?}",
                        spec.name,
                        table.difference(&wgsl).collect::<Vec<_>>(),
                        wgsl.difference(&table).collect::<Vec<_>>(),
                    ));
                }
            }
        }
        assert!(failures.is_empty(), "{}", failures.join("\n"));
    }

    #[test]
    fn kernel_names_are_unique() {
        let names: BTreeSet<&str> = KERNELS.iter().map(|k| k.name).collect();
        assert_eq!(names.len(), KERNELS.len());
    }

    /// Every file of `shaders/` is in the table's list of files, and every listed file goes into
    /// some kernel under some variant.
    #[test]
    fn every_shader_file_is_used() {
        let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("shaders");
        let on_disk: BTreeSet<String> = std::fs::read_dir(&dir)
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .filter(|name| name.ends_with(".wgsl"))
            .collect();
        let listed: BTreeSet<String> = file::ALL
            .iter()
            .map(|p| p.file(Variant::ALL[0]).0.to_owned())
            .collect();
        assert_eq!(on_disk, listed, "shaders/ and the table's files differ");
        let used: BTreeSet<String> = KERNELS
            .iter()
            .flat_map(|spec| Variant::ALL.into_iter().flat_map(move |v| spec.files(v)))
            .map(|(name, _)| name.to_owned())
            .collect();
        let unused: Vec<_> = listed.difference(&used).collect();
        assert!(unused.is_empty(), "files no kernel uses: {unused:?}");
    }
}
