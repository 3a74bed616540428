//! Macros that generate families of C entry points from one description each, instead of
//! writing out dozens of near-identical functions:
//!
//! - [`vector_fns!`]: the scalar/vector pairs of a per-vertex attribute (glVertex2s and
//!   glVertex2sv, …, glColor4ui and glColor4uiv). Each line gives the parameter names of
//!   one arity and, per C type, the scalar function, the vector function and the type:
//!   `(x, y) glVertex2s glVertex2sv GLshort, glVertex2i glVertex2iv GLint;`. The family
//!   header names the sink (`fn([f32; N])`), the [`Component`] conversion (`cast` or
//!   `norm`) and the values of the components the function does not give. A parameter
//!   list `(target: GLenum; s, t)` puts `target` first in both forms and passes it to the
//!   sink first (glMultiTexCoord).
//! - [`c_fns!`]: functions of one line each, `safe fn NAME(PARAMS) -> RET => EXPR;`, and
//!   extension names that forward to their core function,
//!   `safe fn glBindBufferARB(target: GLenum, buffer: GLuint) = buffers::glBindBuffer;`
//!   (`unsafe fn` for an unsafe one: its body runs in an `unsafe` block). `///` lines
//!   before an entry are its doc.
//!
//! # How the header generator and the proc table see generated functions
//!
//! cbindgen does not expand macros, and build.rs (the OSMesaGetProcAddress table), the
//! tests (tests/headers.rs, tests/robust_common) and tools/gen_aliases.py read `src/ffi`
//! as text. So every C name and signature stands in the invocation literally, in the
//! line formats above, and `tools/ffi_expand.rs` (one implementation, included with
//! `#[path]` by build.rs, the generator and the tests; tools/gen_aliases.py mirrors its
//! few lines) rewrites each invocation, in place, into the plain
//! `#[no_mangle] pub extern "C" fn NAME(PARAMS) {}` declarations the scanners already
//! read: cbindgen renders the same prototypes in the same order as for hand-written
//! functions, so the headers stay byte-identical. An invocation starts with a line
//! `vector_fns! {` or `c_fns! {` and ends with a line that is only `}`.
#![allow(non_snake_case)]

use super::types::*;

/// A GL scalar type converted to the `f32` of a vertex attribute.
pub(crate) trait Component: Copy {
    /// The value as a float (positions, texture coordinates): `c as f32`.
    fn cast(self) -> f32;
    /// A colour or normal component, as Mesa's vbo module converts it: `(2c + 1) / (2^n -
    /// 1)` for signed integers, `c / (2^n - 1)` for unsigned ones, floats unchanged.
    fn norm(self) -> f32;
}

impl Component for GLbyte {
    fn cast(self) -> f32 {
        self as f32
    }
    fn norm(self) -> f32 {
        (2.0 * self as f32 + 1.0) * (1.0 / 255.0)
    }
}

impl Component for GLshort {
    fn cast(self) -> f32 {
        self as f32
    }
    fn norm(self) -> f32 {
        (2.0 * self as f32 + 1.0) * (1.0 / 65535.0)
    }
}

impl Component for GLint {
    fn cast(self) -> f32 {
        self as f32
    }
    fn norm(self) -> f32 {
        ((2.0 * self as f64 + 1.0) * (1.0 / 4294967294.0)) as f32
    }
}

impl Component for GLubyte {
    fn cast(self) -> f32 {
        self as f32
    }
    fn norm(self) -> f32 {
        self as f32 / 255.0
    }
}

impl Component for GLushort {
    fn cast(self) -> f32 {
        self as f32
    }
    fn norm(self) -> f32 {
        self as f32 / 65535.0
    }
}

impl Component for GLuint {
    fn cast(self) -> f32 {
        self as f32
    }
    fn norm(self) -> f32 {
        (self as f64 / 4294967295.0) as f32
    }
}

impl Component for GLfloat {
    fn cast(self) -> f32 {
        self
    }
    fn norm(self) -> f32 {
        self
    }
}

impl Component for GLdouble {
    fn cast(self) -> f32 {
        self as f32
    }
    fn norm(self) -> f32 {
        self as f32
    }
}

/// `defaults` with its first `M` components replaced by `given`.
#[inline]
pub(crate) fn fill<const N: usize, const M: usize>(
    mut defaults: [f32; N],
    given: [f32; M],
) -> [f32; N] {
    defaults[..M].copy_from_slice(&given);
    defaults
}

/// Generates the scalar/vector entry points of per-vertex attributes (see the module
/// doc for the format).
macro_rules! vector_fns {
    ($($sink:ident $conv:ident $defaults:tt {
        $($params:tt $($name:ident $vname:ident $t:ty),+;)+
    })+) => {
        $($($(
            $crate::ffi::families::vector_fns!(@one $sink $conv $defaults $params $name $vname $t);
        )+)+)+
    };
    (@one $sink:ident $conv:ident $defaults:tt ($f:ident: $ft:ty; $($p:ident),+)
        $name:ident $vname:ident $t:ty) => {
        $crate::ffi::families::vector_fns!(@gen [$f: $ft] $sink $conv $defaults ($($p),+)
            $name $vname $t);
    };
    (@one $sink:ident $conv:ident $defaults:tt ($($p:ident),+) $name:ident $vname:ident
        $t:ty) => {
        $crate::ffi::families::vector_fns!(@gen [] $sink $conv $defaults ($($p),+) $name
            $vname $t);
    };
    (@gen [$($f:ident: $ft:ty)?] $sink:ident $conv:ident $defaults:tt ($($p:ident),+)
        $name:ident $vname:ident $t:ty) => {
        #[doc = concat!("`", stringify!($name), "`: calls `", stringify!($sink), "` with ",
            "the `", stringify!($conv), "` conversion of its arguments.")]
        #[no_mangle]
        pub extern "C" fn $name($($f: $ft,)? $($p: $t),+) {
            use $crate::ffi::families::Component as _;
            $sink($($f,)? $crate::ffi::families::fill($defaults, [$($p.$conv()),+]))
        }

        #[doc = concat!("`", stringify!($vname), "`: `", stringify!($name),
            "` with its arguments read from `v` (nothing happens when `v` is null).")]
        ///
        /// # Safety
        /// `v` must be null or point to as many values as the scalar form takes.
        #[no_mangle]
        pub unsafe extern "C" fn $vname($($f: $ft,)? v: *const $t) {
            use $crate::ffi::families::Component as _;
            const N: usize = [$(stringify!($p)),+].len();
            if v.is_null() {
                return;
            }
            let given: [f32; N] = std::array::from_fn(|i| {
                // SAFETY: the caller promises N readable values (aligned or not).
                unsafe { v.add(i).read_unaligned() }.$conv()
            });
            $sink($($f,)? $crate::ffi::families::fill($defaults, given))
        }
    };
}
pub(crate) use vector_fns;

/// Generates one-line C functions (see the module doc for the format).
macro_rules! c_fns {
    (@body [$($doc:tt)*] $safety:ident $name:ident ($($p:ident: $t:ty),*) ($($r:ty)?)
        ($m:ident $core:ident) ()) => {
        $crate::ffi::families::c_fns!(@fn [$($doc)*
            #[doc = concat!("`", stringify!($name), "`: the extension name of [`super::",
                stringify!($m), "::", stringify!($core), "`].")]]
            $safety $name ($($p: $t),*) ($($r)?) (super::$m::$core($($p),*)));
    };
    (@body [$($doc:tt)*] $safety:ident $name:ident ($($p:ident: $t:ty),*) ($($r:ty)?)
        () ($body:expr)) => {
        $crate::ffi::families::c_fns!(@fn [#[doc = concat!(stringify!($name), ".")] $($doc)*]
            $safety $name ($($p: $t),*) ($($r)?) ($body));
    };
    (@fn [$($doc:tt)*] safe $name:ident ($($p:ident: $t:ty),*) ($($r:ty)?) ($body:expr)) => {
        $($doc)*
        #[no_mangle]
        pub extern "C" fn $name($($p: $t),*) $(-> $r)? {
            $body
        }
    };
    (@fn [$($doc:tt)*] unsafe $name:ident ($($p:ident: $t:ty),*) ($($r:ty)?) ($body:expr)) => {
        $($doc)*
        ///
        /// # Safety
        /// The pointer arguments must be valid as the GL specification requires.
        #[no_mangle]
        pub unsafe extern "C" fn $name($($p: $t),*) $(-> $r)? {
            // SAFETY: the caller upholds the function's contract; the body passes the
            // arguments on unchanged.
            unsafe { $body }
        }
    };
    ($($(#[$doc:meta])* $safety:ident fn $name:ident($($p:ident: $t:ty),*) $(-> $r:ty)?
        $(= $m:ident::$core:ident)? $(=> $body:expr)?;)+) => {
        $($crate::ffi::families::c_fns!(@body [$(#[$doc])*] $safety $name ($($p: $t),*)
            ($($r)?) ($($m $core)?) ($($body)?));)+
    };
}
pub(crate) use c_fns;
