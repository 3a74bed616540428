//! glCallLists: the lists `base + name` for each name, in order.

use super::Context;

impl Context {
    /// glCallLists on names already read from the client's array (see [`Context::call_list`]).
    pub(crate) fn call_lists(&mut self, names: &[u32]) {
        let base = self.lists.base;
        for &k in names {
            self.call_list(base.wrapping_add(k));
        }
    }
}
