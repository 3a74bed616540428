//! The pool's side of a draw thread's batches ([`super`]): the job slot through which a
//! batch (or a side task of a split draw) is handed to a pool task, which draws it and
//! then polls a while for the next one before it gives its thread back.

use super::Work;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, Condvar, Mutex};
use std::time::{Duration, Instant};

/// A value alone on its 128 bytes (two cache lines, which AMD and Intel prefetch as a
/// pair): a thread that polls it is not slowed down by another thread writing its
/// neighbours, and writes to it do not slow down readers of theirs (false sharing).
#[repr(align(128))]
pub(super) struct Padded<T>(pub(super) T);

impl<T> std::ops::Deref for Padded<T> {
    type Target = T;
    fn deref(&self) -> &T {
        &self.0
    }
}

/// The pool's side of a draw thread's batches: whether the batch handed over is drawn,
/// and the hand-over slot of a pool task that stays on after a batch ([`Job::run`]).
/// Aligned to lines of its own: a pool task polls `posted` while the draw thread works on
/// whatever the allocator would have put next to it.
#[derive(Default)]
#[repr(align(128))]
pub(super) struct Job {
    /// The same as `slot.busy`, for waiting without the lock.
    pub(super) busy: AtomicBool,
    /// Set when `slot.next` holds a batch for the task that waits in [`Job::run`].
    posted: AtomicBool,
    slot: Mutex<Slot>,
    /// Signalled when `busy` goes false.
    done: Condvar,
}

/// The state of a [`Job`] behind its lock.
#[derive(Default)]
struct Slot {
    /// A batch was handed over and is not drawn yet.
    busy: bool,
    /// A pool task has finished its batch and waits for the next one in [`Job::run`].
    waiting: bool,
    /// The task handed to that pool task.
    next: Option<Task>,
}

/// What a [`Job`] runs on the pool.
pub(super) enum Task {
    /// A batch, drawn band by band.
    Bands(Arc<Work>),
    /// A closure on the draw thread's stack ([`Rasterizer::split_geometry`]), called once.
    Side(SideFn),
    /// Nothing: gets a pool thread running, which then waits for the next task
    /// ([`Rasterizer::start_pool`]).
    Start,
}

/// A pointer to a closure that the draw thread keeps alive (and waits for, through
/// [`Job::wait_done`]) until the pool task that calls it has reported done.
pub(super) struct SideFn(pub(super) *const (dyn Fn() + Sync + 'static));

// SAFETY: the closure is `Sync`, so calling it from the pool thread through a shared
// pointer is allowed; the draw thread keeps it alive until the call has returned.
unsafe impl Send for SideFn {}

impl Job {
    /// Runs `work` on the pool, using a task that waits for more if there is one
    /// (see [`Job::run`]).
    pub(super) fn hand_over(self: &Arc<Self>, work: Task, helpers: usize, stay: Duration) {
        // Only a `Task::Start` is handed over without the draw thread waiting for it later;
        // the next task waits until it has run (the pool thread is up by then).
        if self.busy.load(Ordering::Acquire) {
            self.wait_done(crate::tuning::tuning().pool_spin);
        }
        let mut slot = self.slot.lock().unwrap_or_else(|e| e.into_inner());
        slot.busy = true;
        self.busy.store(true, Ordering::Release);
        if slot.waiting {
            slot.waiting = false;
            slot.next = Some(work);
            self.posted.store(true, Ordering::Release);
            return;
        }
        drop(slot);
        let job = Arc::clone(self);
        rayon::spawn(move || job.run(work, helpers, stay));
    }

    /// Hands `work` to the pool task that polls for its next one, if a task polls now and
    /// nothing is handed over; else returns it. Never starts a pool thread: that takes a
    /// good part of a millisecond, more than a draw's side task saves.
    pub(super) fn try_post(&self, work: Task) -> Result<(), Task> {
        if self.busy.load(Ordering::Acquire) {
            return Err(work);
        }
        let mut slot = self.slot.lock().unwrap_or_else(|e| e.into_inner());
        if slot.busy || !slot.waiting {
            return Err(work);
        }
        slot.busy = true;
        self.busy.store(true, Ordering::Release);
        slot.waiting = false;
        slot.next = Some(work);
        self.posted.store(true, Ordering::Release);
        Ok(())
    }

    /// A pool task: draws `work` on `helpers` threads, reports it done, then keeps polling
    /// for the next batch of this draw thread for `stay` before it returns the pool thread.
    /// Waking a sleeping pool thread takes a good part of a millisecond on this kind of
    /// virtual machine, longer than the work of a small frame; frames follow each other
    /// within that time.
    fn run(&self, mut work: Task, helpers: usize, stay: Duration) {
        loop {
            match work {
                Task::Bands(work) => {
                    let helpers = helpers.min(rayon::current_num_threads());
                    if helpers > 1 {
                        let w = &work;
                        rayon::scope(|s| {
                            for _ in 1..helpers {
                                s.spawn(|_| w.help());
                            }
                            w.help();
                        });
                    } else {
                        work.help();
                    }
                    // The draw thread takes the batch back with `Arc::into_inner`: drop
                    // ours first.
                    drop(work);
                }
                Task::Side(f) => {
                    // A panic stays on this thread (the closure tells the draw thread to
                    // stop through its own state); the job still reports done.
                    // SAFETY: the draw thread keeps the closure alive until `busy` goes
                    // false below (see `SideFn`).
                    let f = unsafe { &*f.0 };
                    let _ = std::panic::catch_unwind(std::panic::AssertUnwindSafe(f));
                }
                Task::Start => {}
            }
            {
                let mut slot = self.slot.lock().unwrap_or_else(|e| e.into_inner());
                slot.busy = false;
                slot.waiting = !stay.is_zero();
                self.busy.store(false, Ordering::Release);
            }
            self.done.notify_all();
            if stay.is_zero() {
                return;
            }
            poll(stay, || self.posted.load(Ordering::Acquire));
            let mut slot = self.slot.lock().unwrap_or_else(|e| e.into_inner());
            match slot.next.take() {
                Some(next) => {
                    self.posted.store(false, Ordering::Relaxed);
                    work = next;
                }
                None => {
                    slot.waiting = false;
                    return;
                }
            }
        }
    }

    /// Waits until the batch handed over is drawn: polls for `spin` first (the pool
    /// thread is finishing its last band), then sleeps.
    pub(super) fn wait_done(&self, spin: Duration) {
        if self.busy.load(Ordering::Acquire) && !spin.is_zero() {
            poll(spin, || !self.busy.load(Ordering::Acquire));
        }
        let mut slot = self.slot.lock().unwrap_or_else(|e| e.into_inner());
        while slot.busy {
            slot = self.done.wait(slot).unwrap_or_else(|e| e.into_inner());
        }
    }
}

/// Polls `ready` until it holds or `limit` has passed. Past
/// [`crate::tuning::Tuning::pool_yield`] the thread yields its core between checks: on a
/// busy machine (two cores shared with other processes, or with this process's own
/// threads) the polling then costs the others little CPU, while on an idle one
/// `sched_yield` returns at once and the thread sees `ready` as soon as before, without
/// the wake-up a sleep would need.
fn poll(limit: Duration, ready: impl Fn() -> bool) {
    let start = Instant::now();
    let yield_after = crate::tuning::tuning().pool_yield.min(limit);
    let mut spins = 0u32;
    let mut yielding = false;
    while !ready() {
        if yielding {
            std::thread::yield_now();
        } else {
            std::hint::spin_loop();
        }
        spins = spins.wrapping_add(1);
        if yielding || spins.is_multiple_of(64) {
            let t = start.elapsed();
            if t >= limit {
                return;
            }
            yielding = t >= yield_after;
        }
    }
}
