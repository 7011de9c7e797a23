//! Work spread over threads natively and done in order on wasm32, where there are none,
//! with the same results either way: each item's result depends only on its index.

/// Maps `f` over `0..count`, in parallel where threads exist, keeping the order.
pub fn map_indices<T: Send>(count: usize, f: impl Fn(usize) -> T + Sync + Send) -> Vec<T> {
    #[cfg(not(target_arch = "wasm32"))]
    {
        use rayon::prelude::*;
        (0..count).into_par_iter().map(f).collect()
    }
    #[cfg(target_arch = "wasm32")]
    {
        (0..count).map(f).collect()
    }
}

/// How many threads work is spread over: one on wasm32.
pub fn threads() -> usize {
    #[cfg(not(target_arch = "wasm32"))]
    {
        rayon::current_num_threads()
    }
    #[cfg(target_arch = "wasm32")]
    {
        1
    }
}

/// Runs `a`, and `b` on another thread if one takes it up while `a` runs; `b`'s result,
/// or `None` when no thread took it, and then `b` does not run at all.
pub fn join_helped<A: Send, B: Send>(
    a: impl FnOnce() -> A + Send,
    b: impl FnOnce() -> B + Send,
) -> (A, Option<B>) {
    #[cfg(not(target_arch = "wasm32"))]
    {
        rayon::join_context(|_| a(), |context| context.migrated().then(b))
    }
    #[cfg(target_arch = "wasm32")]
    {
        let _ = b;
        (a(), None)
    }
}

/// Keeps this thread taking up other threads' pending work (as [`join_helped`] offers it)
/// until `done` holds, without going to sleep: for a thread whose share of some work ended
/// before the others', which a sleeping thread would take up tens of microseconds late.
/// Returns at once on wasm32 and outside a thread pool.
pub fn help_until(done: impl Fn() -> bool) {
    #[cfg(not(target_arch = "wasm32"))]
    while !done() {
        match rayon::yield_now() {
            Some(rayon::Yield::Executed) => {}
            Some(rayon::Yield::Idle) => std::hint::spin_loop(),
            None => return,
        }
    }
    #[cfg(target_arch = "wasm32")]
    let _ = done;
}

/// Runs `a` and `b`, at once where threads exist, and returns both results.
pub fn join<A: Send, B: Send>(
    a: impl FnOnce() -> A + Send,
    b: impl FnOnce() -> B + Send,
) -> (A, B) {
    #[cfg(not(target_arch = "wasm32"))]
    {
        rayon::join(a, b)
    }
    #[cfg(target_arch = "wasm32")]
    {
        (a(), b())
    }
}
