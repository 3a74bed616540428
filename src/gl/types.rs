//! The Khronos scalar types of the GL C API (`GLenum`, `GLfloat`, …) with their C sizes.
#![allow(non_camel_case_types, missing_docs)]

use libc::{c_char, c_double, c_float, c_int, c_schar, c_short, c_uchar, c_uint, c_ushort};

pub type GLenum = c_uint;
pub type GLboolean = c_uchar;
pub type GLbitfield = c_uint;
pub type GLvoid = libc::c_void;
pub type GLbyte = c_schar;
pub type GLshort = c_short;
pub type GLint = c_int;
pub type GLubyte = c_uchar;
pub type GLushort = c_ushort;
pub type GLuint = c_uint;
pub type GLsizei = c_int;
pub type GLfloat = c_float;
pub type GLclampf = c_float;
pub type GLdouble = c_double;
pub type GLclampd = c_double;
pub type GLchar = c_char;
pub type GLsizeiptr = isize;
pub type GLintptr = isize;
