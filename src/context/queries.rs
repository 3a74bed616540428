//! Occlusion query objects (GL 1.5 / ARB_occlusion_query), with Mesa's rules: names from
//! glGenQueries exist but are not queries (glIsQuery FALSE) until first begun; the
//! compatibility profile also accepts names never generated; deleting the active query
//! ends it.
//!
//! The count is the difference of the context's `samples_passed` counter between
//! glBeginQuery and glEndQuery; the fragment stage counts only while a query is active,
//! so no query costs nothing.

use std::collections::HashMap;

use super::{Context, GlError, GlResult};

/// One query object.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct QueryObject {
    /// Begun at least once (glIsQuery).
    pub ever_bound: bool,
    /// The result of the last finished query.
    pub result: u64,
}

/// The query objects of a context and the active GL_SAMPLES_PASSED query.
#[derive(Clone, Debug, Default)]
pub struct QueryState {
    /// Objects by name (generated names included).
    pub objects: HashMap<u32, QueryObject>,
    /// The active query: its name and the sample counter at glBeginQuery.
    pub active: Option<(u32, u64)>,
}

impl Context {
    /// glGenQueries: `n` unused names.
    pub fn gen_queries(&mut self, n: usize) -> GlResult<Vec<u32>> {
        let q = &mut self.queries.objects;
        let mut out = Vec::with_capacity(n.min(1 << 16));
        let mut next = 1u32;
        while out.len() < n {
            if let std::collections::hash_map::Entry::Vacant(e) = q.entry(next) {
                e.insert(QueryObject::default());
                out.push(next);
            }
            next = next.checked_add(1).ok_or(GlError::OutOfMemory)?;
        }
        Ok(out)
    }

    /// glDeleteQueries (an active query is ended first; unknown names are ignored).
    pub fn delete_queries(&mut self, names: &[u32]) -> GlResult<()> {
        for &name in names {
            if self.queries.active.is_some_and(|(a, _)| a == name) {
                self.queries.active = None;
            }
            self.queries.objects.remove(&name);
        }
        Ok(())
    }

    /// glIsQuery.
    pub fn is_query(&self, name: u32) -> GlResult<bool> {
        Ok(self
            .queries
            .objects
            .get(&name)
            .is_some_and(|q| q.ever_bound))
    }

    /// glBeginQuery(GL_SAMPLES_PASSED, name).
    pub fn begin_query(&mut self, name: u32) -> GlResult<()> {
        if name == 0 || self.queries.active.is_some() {
            return Err(GlError::InvalidOperation);
        }
        let q = self.queries.objects.entry(name).or_default();
        q.ever_bound = true;
        q.result = 0;
        self.queries.active = Some((name, self.stats.samples_passed));
        Ok(())
    }

    /// glEndQuery(GL_SAMPLES_PASSED).
    pub fn end_query(&mut self) -> GlResult<()> {
        let Some((name, start)) = self.queries.active.take() else {
            return Err(GlError::InvalidOperation);
        };
        if let Some(q) = self.queries.objects.get_mut(&name) {
            q.result = self.stats.samples_passed.saturating_sub(start);
        }
        Ok(())
    }

    /// glGetQueryObject's GL_QUERY_RESULT (results are always available: softgl draws
    /// synchronously). Fails for names that are not queries or the active one.
    pub fn query_result(&self, name: u32) -> GlResult<u64> {
        match self.queries.objects.get(&name) {
            Some(q) if q.ever_bound && self.queries.active.map(|a| a.0) != Some(name) => {
                Ok(q.result)
            }
            _ => Err(GlError::InvalidOperation),
        }
    }
}
