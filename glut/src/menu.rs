//! GLUT menus, headless: they are never shown, but keep the state a program can
//! observe as freeglut keeps it. Menu ids count up from 1 and are never reused;
//! creating a menu makes it current; items are numbered from 1; a destroyed menu is
//! detached from every window and every sub-menu entry leading to it loses its
//! sub-menu (the entry stays), and its destroy callback runs with it current.
//! Calls naming a missing menu or item do nothing.

#![allow(non_snake_case)]

use std::cell::RefCell;
use std::collections::BTreeMap;
use std::ffi::{c_char, c_int, c_void, CStr};

/// freeglut's number of mouse buttons a menu can be attached to.
const MAX_BUTTONS: c_int = 3;

/// One menu item: a label with a value, or a sub-menu. Labels and values are kept as
/// freeglut keeps them, though nothing headless reads them.
#[allow(dead_code)]
struct Entry {
    label: String,
    value: c_int,
    sub: Option<c_int>,
}

/// A menu (its selection callback is kept, never called: menus never open).
#[allow(dead_code)]
struct Menu {
    entries: Vec<Entry>,
    callback: Option<extern "C" fn(c_int)>,
    destroy: Option<extern "C" fn()>,
    data: *mut c_void,
}

/// Every menu, the current one, which menus windows have attached, and the menu
/// state/status callbacks (kept, never called).
#[allow(dead_code)]
struct Menus {
    menus: BTreeMap<c_int, Menu>,
    last_id: c_int,
    current: c_int,
    /// (window, button) → menu.
    attached: BTreeMap<(c_int, c_int), c_int>,
    state_cb: Option<extern "C" fn(c_int)>,
    status_cb: Option<extern "C" fn(c_int, c_int, c_int)>,
}

thread_local! {
    static MENUS: RefCell<Menus> = const {
        RefCell::new(Menus {
            menus: BTreeMap::new(),
            last_id: 0,
            current: 0,
            attached: BTreeMap::new(),
            state_cb: None,
            status_cb: None,
        })
    };
}

/// Runs `f` on the menu state. Never call a user callback inside `f`.
fn with<R>(f: impl FnOnce(&mut Menus) -> R) -> R {
    MENUS.with(|m| f(&mut m.borrow_mut()))
}

/// Runs `f` on the current menu, if any.
fn with_current<R: Default>(f: impl FnOnce(&mut Menu) -> R) -> R {
    with(|m| {
        let id = m.current;
        m.menus.get_mut(&id).map(f).unwrap_or_default()
    })
}

fn label(s: *const c_char) -> String {
    if s.is_null() {
        return String::new();
    }
    // SAFETY: a non-null label is a NUL-terminated C string (GLUT's contract).
    unsafe { CStr::from_ptr(s) }.to_string_lossy().into_owned()
}

/// The number of items of the current menu (`glutGet(GLUT_MENU_NUM_ITEMS)`).
pub fn num_items() -> c_int {
    with_current(|m| m.entries.len() as c_int)
}

/// Forgets what window `id` had attached (the window is gone).
pub fn window_destroyed(id: c_int) {
    with(|m| m.attached.retain(|&(w, _), _| w != id));
}

/// `glutCreateMenu`: a new, current, empty menu; returns its id.
#[no_mangle]
pub extern "C" fn glutCreateMenu(callback: Option<extern "C" fn(c_int)>) -> c_int {
    with(|m| {
        m.last_id += 1;
        let id = m.last_id;
        m.menus.insert(
            id,
            Menu {
                entries: Vec::new(),
                callback,
                destroy: None,
                data: std::ptr::null_mut(),
            },
        );
        m.current = id;
        id
    })
}

/// `glutDestroyMenu`.
#[no_mangle]
pub extern "C" fn glutDestroyMenu(id: c_int) {
    let Some(destroy) = with(|m| m.menus.get(&id).map(|menu| menu.destroy)) else {
        return;
    };
    if let Some(f) = destroy {
        let saved = with(|m| std::mem::replace(&mut m.current, id));
        f();
        with(|m| m.current = saved);
    }
    with(|m| {
        m.menus.remove(&id);
        m.attached.retain(|_, menu| *menu != id);
        for menu in m.menus.values_mut() {
            for e in &mut menu.entries {
                if e.sub == Some(id) {
                    e.sub = None;
                }
            }
        }
        if m.current == id {
            m.current = 0;
        }
    });
}

/// `glutGetMenu`: the current menu's id, 0 when there is none.
#[no_mangle]
pub extern "C" fn glutGetMenu() -> c_int {
    with(|m| m.current)
}

/// `glutSetMenu`: makes an existing menu current.
#[no_mangle]
pub extern "C" fn glutSetMenu(id: c_int) {
    with(|m| {
        if m.menus.contains_key(&id) {
            m.current = id;
        }
    });
}

/// `glutAddMenuEntry`: appends an item to the current menu.
#[no_mangle]
pub extern "C" fn glutAddMenuEntry(text: *const c_char, value: c_int) {
    let label = label(text);
    with_current(|m| {
        m.entries.push(Entry {
            label,
            value,
            sub: None,
        })
    });
}

/// `glutAddSubMenu`: appends an item opening menu `sub` (which must exist).
#[no_mangle]
pub extern "C" fn glutAddSubMenu(text: *const c_char, sub: c_int) {
    if !with(|m| m.menus.contains_key(&sub)) {
        return;
    }
    let label = label(text);
    with_current(|m| {
        m.entries.push(Entry {
            label,
            value: -1,
            sub: Some(sub),
        })
    });
}

/// Runs `f` on item `item` (from 1) of the current menu.
fn with_item(item: c_int, f: impl FnOnce(&mut Entry)) {
    with_current(|m| {
        if let Some(e) = usize::try_from(item)
            .ok()
            .and_then(|i| i.checked_sub(1))
            .and_then(|i| m.entries.get_mut(i))
        {
            f(e);
        }
    });
}

/// `glutChangeToMenuEntry`: item `item` (from 1) becomes a plain entry.
#[no_mangle]
pub extern "C" fn glutChangeToMenuEntry(item: c_int, text: *const c_char, value: c_int) {
    let label = label(text);
    with_item(item, |e| {
        *e = Entry {
            label,
            value,
            sub: None,
        }
    });
}

/// `glutChangeToSubMenu`: item `item` (from 1) opens menu `sub` (which must exist).
#[no_mangle]
pub extern "C" fn glutChangeToSubMenu(item: c_int, text: *const c_char, sub: c_int) {
    if !with(|m| m.menus.contains_key(&sub)) {
        return;
    }
    let label = label(text);
    with_item(item, |e| {
        *e = Entry {
            label,
            value: -1,
            sub: Some(sub),
        }
    });
}

/// `glutRemoveMenuItem`: removes item `item` (from 1) of the current menu.
#[no_mangle]
pub extern "C" fn glutRemoveMenuItem(item: c_int) {
    with_current(|m| {
        if item >= 1 && (item as usize) <= m.entries.len() {
            m.entries.remove(item as usize - 1);
        }
    });
}

/// Attaches (or with `menu` None detaches) on the current window's `button`.
fn attach(button: c_int, menu: Option<c_int>) {
    let window = crate::window::glutGetWindow();
    with(|m| {
        if window == 0 || m.current == 0 || !(0..MAX_BUTTONS).contains(&button) {
            return;
        }
        match menu {
            Some(_) => {
                let current = m.current;
                m.attached.insert((window, button), current);
            }
            None => {
                m.attached.remove(&(window, button));
            }
        }
    });
}

/// `glutAttachMenu`: the current menu opens on `button` in the current window
/// (never, headless).
#[no_mangle]
pub extern "C" fn glutAttachMenu(button: c_int) {
    attach(button, Some(0));
}

/// `glutDetachMenu`.
#[no_mangle]
pub extern "C" fn glutDetachMenu(button: c_int) {
    attach(button, None);
}

/// `glutMenuStateFunc` (menus never open, so it is never called).
#[no_mangle]
pub extern "C" fn glutMenuStateFunc(f: Option<extern "C" fn(c_int)>) {
    with(|m| m.state_cb = f);
}

/// `glutMenuStatusFunc` (menus never open, so it is never called).
#[no_mangle]
pub extern "C" fn glutMenuStatusFunc(f: Option<extern "C" fn(c_int, c_int, c_int)>) {
    with(|m| m.status_cb = f);
}

/// `glutMenuDestroyFunc` (freeglut): called when the current menu is destroyed.
#[no_mangle]
pub extern "C" fn glutMenuDestroyFunc(f: Option<extern "C" fn()>) {
    with_current(|m| m.destroy = f);
}

/// `glutSetMenuFont` (freeglut): menus are not drawn; accepted.
#[no_mangle]
pub extern "C" fn glutSetMenuFont(_menu: c_int, _font: *mut c_void) {}

/// `glutGetMenuData` (freeglut): the current menu's user data (NULL without one).
#[no_mangle]
pub extern "C" fn glutGetMenuData() -> *mut c_void {
    with_current(|m| Some(m.data)).unwrap_or(std::ptr::null_mut())
}

/// `glutSetMenuData` (freeglut).
#[no_mangle]
pub extern "C" fn glutSetMenuData(data: *mut c_void) {
    with_current(|m| m.data = data);
}

#[cfg(test)]
mod tests {
    use super::*;

    extern "C" fn pick(_: c_int) {}

    #[test]
    fn ids_items_and_destruction() {
        let a = glutCreateMenu(Some(pick));
        let b = glutCreateMenu(None);
        assert_eq!((a + 1, glutGetMenu()), (b, b));
        glutAddMenuEntry(c"one".as_ptr(), 1);
        glutAddSubMenu(c"to a".as_ptr(), a);
        glutAddSubMenu(c"to nothing".as_ptr(), 999);
        assert_eq!(num_items(), 2);
        glutChangeToMenuEntry(2, c"two".as_ptr(), 2);
        glutRemoveMenuItem(1);
        glutRemoveMenuItem(5);
        assert_eq!(num_items(), 1);
        glutDestroyMenu(b);
        assert_eq!(glutGetMenu(), 0);
        assert_eq!(glutCreateMenu(None), b + 1);
        glutSetMenu(a);
        assert_eq!(glutGetMenu(), a);
        assert_eq!(num_items(), 0);
    }
}
