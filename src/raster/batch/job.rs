//! The pool's side of a draw thread's batches ([`super`]): the job slot through which a
//! batch (or a side task of a split draw) is handed to a pool task, which draws it and
//! then polls a while for the next one before it gives its thread back.
//!
//! The slot takes a task whenever the draw thread hands one over, also while the pool
//! task is still finishing the previous one (it is queued and the task takes it next): a
//! batch is known drawn from its own count of drawn bands ([`super::Work::drawn`]), so
//! the draw thread does not wait for the task to report before it takes the batch back
//! and hands over the next (stop 59, docs/performance.md). Side tasks and
//! [`Job::wait_done`] still go by the tasks' reports.

use super::Work;
use std::collections::VecDeque;
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

/// The pool's side of a draw thread's batches: whether the tasks handed over have run,
/// and the hand-over queue of a pool task that stays on after a task ([`Job::run`]).
/// Aligned to lines of its own: a pool task polls `posted` while the draw thread works on
/// whatever the allocator would have put next to it.
#[derive(Default)]
#[repr(align(128))]
pub(super) struct Job {
    /// Whether a task handed over has not reported done yet (`slot.handed !=
    /// slot.finished`), for waiting without the lock.
    pub(super) busy: AtomicBool,
    /// Set while `slot.next` holds a task for the pool task ([`Job::run`]).
    posted: AtomicBool,
    slot: Mutex<Slot>,
    /// Signalled when a task reports done.
    done: Condvar,
    /// The buffers of a batch whose last handle the pool task dropped (the draw thread had
    /// already let go of it), for the draw thread's next batch ([`Job::returned`]).
    returned: Mutex<Option<super::Batch>>,
}

/// The state of a [`Job`] behind its lock.
#[derive(Default)]
struct Slot {
    /// Tasks handed over.
    handed: u64,
    /// Tasks that have run.
    finished: u64,
    /// A pool task is running: it takes `next` before it returns its thread.
    alive: bool,
    /// The tasks handed to that pool task, in order.
    next: VecDeque<Task>,
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
    /// Runs `work` on the pool: queued for the pool task of this slot if one is running
    /// (it may still be finishing the previous task), else on a new one (see
    /// [`Job::run`]).
    pub(super) fn hand_over(self: &Arc<Self>, work: Task, helpers: usize, stay: Duration) {
        let mut slot = self.slot.lock().unwrap_or_else(|e| e.into_inner());
        slot.handed += 1;
        self.busy.store(true, Ordering::Release);
        if slot.alive {
            slot.next.push_back(work);
            self.posted.store(true, Ordering::Release);
            return;
        }
        slot.alive = true;
        drop(slot);
        let job = Arc::clone(self);
        rayon::spawn(move || job.run(work, helpers, stay));
    }

    /// A pool task: runs `work` on `helpers` threads, reports it done, runs the tasks
    /// queued meanwhile, then keeps polling for the next task of this draw thread for
    /// `stay` before it returns the pool thread. Waking a sleeping pool thread takes a
    /// good part of a millisecond on this kind of virtual machine, longer than the work of
    /// a small frame; frames follow each other within that time.
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
                    // The last handle keeps the buffers for the draw thread's next batch.
                    if let Some(w) = Arc::into_inner(work) {
                        let mut r = self.returned.lock().unwrap_or_else(|e| e.into_inner());
                        if r.is_none() {
                            *r = Some(w.batch);
                        }
                    }
                }
                Task::Side(f) => {
                    // A panic stays on this thread (the closure tells the draw thread to
                    // stop through its own state); the job still reports done.
                    // SAFETY: the draw thread keeps the closure alive until this task has
                    // reported done below (see `SideFn`).
                    let f = unsafe { &*f.0 };
                    let _ = std::panic::catch_unwind(std::panic::AssertUnwindSafe(f));
                }
                Task::Start => {}
            }
            let next = {
                let mut slot = self.slot.lock().unwrap_or_else(|e| e.into_inner());
                slot.finished += 1;
                self.busy
                    .store(slot.finished != slot.handed, Ordering::Release);
                let next = slot.next.pop_front();
                self.posted.store(!slot.next.is_empty(), Ordering::Release);
                if next.is_none() && stay.is_zero() {
                    slot.alive = false;
                }
                next
            };
            self.done.notify_all();
            if let Some(next) = next {
                work = next;
                continue;
            }
            if stay.is_zero() {
                return;
            }
            poll(stay, || self.posted.load(Ordering::Acquire));
            let mut slot = self.slot.lock().unwrap_or_else(|e| e.into_inner());
            match slot.next.pop_front() {
                Some(next) => {
                    self.posted.store(!slot.next.is_empty(), Ordering::Release);
                    work = next;
                }
                None => {
                    slot.alive = false;
                    return;
                }
            }
        }
    }

    /// Waits until every task handed over has run: polls for `spin` first (the pool
    /// thread is finishing its last band), then sleeps.
    pub(super) fn wait_done(&self, spin: Duration) {
        if self.busy.load(Ordering::Acquire) && !spin.is_zero() {
            poll(spin, || !self.busy.load(Ordering::Acquire));
        }
        let mut slot = self.slot.lock().unwrap_or_else(|e| e.into_inner());
        while slot.finished != slot.handed {
            slot = self.done.wait(slot).unwrap_or_else(|e| e.into_inner());
        }
    }

    /// The buffers of a batch the pool task let go of last, if any.
    pub(super) fn returned(&self) -> Option<super::Batch> {
        self.returned
            .lock()
            .unwrap_or_else(|e| e.into_inner())
            .take()
    }
}

/// Polls `ready` until it holds or `limit` has passed. Past
/// [`crate::tuning::Tuning::pool_yield`] the thread yields its core between checks: on a
/// busy machine (two cores shared with other processes, or with this process's own
/// threads) the polling then costs the others little CPU, while on an idle one
/// `sched_yield` returns at once and the thread sees `ready` as soon as before, without
/// the wake-up a sleep would need.
pub(super) fn poll(limit: Duration, ready: impl Fn() -> bool) {
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

#[cfg(test)]
mod tests {
    use super::*;

    /// Hands `n` side tasks over back to back (most while the pool task still runs the
    /// one before, so they queue) and checks that they ran once each, in order, and that
    /// `wait_done` returned only after the last.
    fn queued_in_order(n: usize, stay: Duration) {
        let job = Arc::new(Job::default());
        let log = Arc::new(Mutex::new(Vec::new()));
        let tasks: Vec<Box<dyn Fn() + Sync>> = (0..n)
            .map(|i| {
                let log = Arc::clone(&log);
                Box::new(move || {
                    std::thread::sleep(Duration::from_micros(50));
                    log.lock().unwrap().push(i);
                }) as Box<dyn Fn() + Sync>
            })
            .collect();
        for t in &tasks {
            let f: *const (dyn Fn() + Sync) = &**t;
            job.hand_over(Task::Side(SideFn(f)), 1, stay);
        }
        // `tasks` outlives the calls: this waits for all of them.
        job.wait_done(Duration::from_micros(100));
        assert!(!job.busy.load(Ordering::Acquire));
        assert_eq!(*log.lock().unwrap(), (0..n).collect::<Vec<_>>());
    }

    #[test]
    fn tasks_handed_over_while_one_runs_queue_in_order() {
        queued_in_order(16, Duration::from_millis(2));
    }

    #[test]
    fn tasks_queue_in_order_without_staying() {
        queued_in_order(16, Duration::ZERO);
    }
}
