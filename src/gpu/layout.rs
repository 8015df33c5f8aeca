//! Rust mirrors of the WGSL uniform and storage structs, declared once with [`wgsl_mirror!`]:
//! the macro writes the `#[repr(C)]` struct and a description of its fields (name, offset, size,
//! scalar type), and each mirror's test (`assert_mirrors`) parses the WGSL of a kernel that reads
//! the struct with naga, lays it out as the device will, and checks that the Rust struct has the
//! WGSL struct's size and, member by member, its names, offsets, sizes and scalar types. A field
//! renamed, swapped, resized or retyped on one side fails there instead of in a parity test. The
//! descriptions exist in test builds only.
//!
//! Uniform blocks name every value (`near: f32`, `width: u32`, explicit `padN` where a block
//! needs padding) instead of packing them positionally into vectors; a vector member is a vector
//! (a rotation column, a camera centre) or an array of values indexed by slot.
//!
//! Threading: plain `Pod` data, written on the calling thread and uploaded by its owner.

/// The scalar type of a WGSL member or of a Rust field's elements.
#[cfg(test)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum ScalarKind {
    F32,
    U32,
    I32,
}

/// Plain data made of one scalar type.
#[cfg(test)]
pub(crate) trait Scalars {
    const KIND: ScalarKind;
}

#[cfg(test)]
impl Scalars for f32 {
    const KIND: ScalarKind = ScalarKind::F32;
}

#[cfg(test)]
impl Scalars for u32 {
    const KIND: ScalarKind = ScalarKind::U32;
}

#[cfg(test)]
impl Scalars for i32 {
    const KIND: ScalarKind = ScalarKind::I32;
}

#[cfg(test)]
impl<T: Scalars, const N: usize> Scalars for [T; N] {
    const KIND: ScalarKind = T::KIND;
}

/// One field of a mirror.
#[cfg(test)]
#[derive(Clone, Copy, Debug)]
pub(crate) struct FieldLayout {
    pub(crate) name: &'static str,
    pub(crate) offset: usize,
    pub(crate) size: usize,
    pub(crate) kind: ScalarKind,
}

/// A `#[repr(C)]` struct that mirrors the WGSL struct `WGSL_NAME`.
#[cfg(test)]
pub(crate) trait WgslMirror: Sized {
    const WGSL_NAME: &'static str;
    fn fields() -> Vec<FieldLayout>;
}

/// Declares a `#[repr(C)]` mirror of a WGSL struct:
/// `wgsl_mirror! { /// doc  #[derive(..)] pub(super) struct ParamsGpu = "Params" { a: [f32; 4], .. } }`.
macro_rules! wgsl_mirror {
    (
        $(#[$meta:meta])*
        $vis:vis struct $name:ident = $wgsl:literal {
            $($(#[$field_meta:meta])* $field_vis:vis $field:ident : $ty:ty),* $(,)?
        }
    ) => {
        $(#[$meta])*
        #[repr(C)]
        $vis struct $name {
            $($(#[$field_meta])* $field_vis $field: $ty),*
        }

        #[cfg(test)]
        impl $crate::gpu::layout::WgslMirror for $name {
            const WGSL_NAME: &'static str = $wgsl;
            fn fields() -> Vec<$crate::gpu::layout::FieldLayout> {
                vec![$($crate::gpu::layout::FieldLayout {
                    name: stringify!($field),
                    offset: std::mem::offset_of!($name, $field),
                    size: std::mem::size_of::<$ty>(),
                    kind: <$ty as $crate::gpu::layout::Scalars>::KIND,
                }),*]
            }
        }
    };
}
pub(crate) use wgsl_mirror;

/// Parses the module of `kernel` (as its pipeline composes it) and asserts that `T` mirrors
/// its WGSL struct: the same size, and field by field the WGSL members in order, each of the same
/// name, offset, size and scalar type.
#[cfg(test)]
pub(crate) fn assert_mirrors<T: WgslMirror>(kernel: &super::shaders::KernelSpec) {
    use naga::{ScalarKind as Kind, TypeInner};
    let source = kernel.source(super::shaders::Variant::ALL[0]);
    let module = naga::front::wgsl::parse_str(&source)
        .unwrap_or_else(|e| panic!("{}", e.emit_to_string(&source)));
    let mut layouter = naga::proc::Layouter::default();
    layouter.update(module.to_ctx()).expect("the WGSL lays out");
    let name = T::WGSL_NAME;
    let (_, ty) = module
        .types
        .iter()
        .find(|(_, t)| t.name.as_deref() == Some(name))
        .unwrap_or_else(|| panic!("no struct `{name}` in the WGSL of `{}`", kernel.name));
    let TypeInner::Struct { members, span } = &ty.inner else {
        panic!("`{name}` is not a struct");
    };
    assert_eq!(
        *span as usize,
        std::mem::size_of::<T>(),
        "size of `{name}` and its Rust mirror"
    );
    let scalar_kind = |inner: &TypeInner| -> ScalarKind {
        let scalar = match inner {
            TypeInner::Scalar(s) | TypeInner::Vector { scalar: s, .. } => *s,
            TypeInner::Matrix { scalar, .. } => *scalar,
            TypeInner::Array { base, .. } => match &module.types[*base].inner {
                TypeInner::Scalar(s) | TypeInner::Vector { scalar: s, .. } => *s,
                other => panic!("`{name}`: unsupported array element {other:?}"),
            },
            other => panic!("`{name}`: unsupported member type {other:?}"),
        };
        match scalar.kind {
            Kind::Float => ScalarKind::F32,
            Kind::Uint => ScalarKind::U32,
            Kind::Sint => ScalarKind::I32,
            other => panic!("`{name}`: unsupported scalar {other:?}"),
        }
    };
    // (name, offset, size, scalar type) of each member.
    let wgsl: Vec<(&str, usize, usize, ScalarKind)> = members
        .iter()
        .map(|m| {
            (
                m.name.as_deref().unwrap_or("?"),
                m.offset as usize,
                layouter[m.ty].size as usize,
                scalar_kind(&module.types[m.ty].inner),
            )
        })
        .collect();
    let rust = T::fields();
    for (i, (field, &(member, offset, size, kind))) in rust.iter().zip(&wgsl).enumerate() {
        let what = format!("`{name}` field {i}");
        assert_eq!(field.name, member, "{what}: Rust and WGSL names");
        assert_eq!(
            (field.offset, field.size),
            (offset, size),
            "{what} `{member}`: bytes (offset, size) in Rust and in WGSL"
        );
        assert_eq!(
            field.kind, kind,
            "{what} `{member}`: scalar type in Rust and in WGSL"
        );
    }
    assert_eq!(
        rust.len(),
        wgsl.len(),
        "`{name}`: fields in Rust ({:?}) and members in WGSL ({:?})",
        rust.iter().map(|f| f.name).collect::<Vec<_>>(),
        wgsl.iter().map(|m| m.0).collect::<Vec<_>>()
    );
}
