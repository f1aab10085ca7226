//! Loops split over threads with a result that does not depend on the number of threads.
//!
//! The items `0..n` are cut into fixed chunks of [`CHUNK`] items (the cut depends only on
//! `n`); worker threads take the chunks in turn and the results come back in chunk order.
//! Each item's work reads shared state and writes only its own result, so whatever the
//! number of threads, the caller sees the same values in the same order, and a drape's
//! positions are the same bytes with one thread or many.

use std::ops::Range;
use std::sync::atomic::{AtomicUsize, Ordering};

/// Items per chunk.
const CHUNK: usize = 128;

/// The number of threads to use for `requested` (0: the machine's available parallelism).
pub(crate) fn threads(requested: usize) -> usize {
    match requested {
        0 => std::thread::available_parallelism().map_or(1, |n| n.get()),
        n => n,
    }
}

/// `work` on every chunk of `0..n`, on up to `threads` threads; the results in chunk order.
pub(crate) fn chunks<T: Send>(threads: usize, n: usize, work: impl Fn(Range<usize>) -> T + Sync) -> Vec<T> {
    let count = n.div_ceil(CHUNK);
    let range = |c: usize| c * CHUNK..((c + 1) * CHUNK).min(n);
    if threads <= 1 || count <= 1 {
        return (0..count).map(|c| work(range(c))).collect();
    }
    let next = AtomicUsize::new(0);
    let worker = || {
        let mut done = Vec::new();
        loop {
            let c = next.fetch_add(1, Ordering::Relaxed);
            if c >= count {
                return done;
            }
            done.push((c, work(range(c))));
        }
    };
    let mut done = std::thread::scope(|s| {
        let helpers: Vec<_> = (1..threads.min(count)).map(|_| s.spawn(worker)).collect();
        let mut done = worker();
        for h in helpers {
            done.extend(h.join().unwrap_or_else(|e| std::panic::resume_unwind(e)));
        }
        done
    });
    done.sort_unstable_by_key(|(c, _)| *c);
    done.into_iter().map(|(_, t)| t).collect()
}

/// `work(i, &mut out[i])` for every item of `out`, on up to `threads` threads: the same
/// fixed chunks as [`chunks`], each written in place (no list per chunk to collect).
pub(crate) fn fill<T: Send>(threads: usize, out: &mut [T], work: impl Fn(usize, &mut T) + Sync) {
    let count = out.len().div_ceil(CHUNK);
    let run = |c: usize, chunk: &mut [T]| {
        for (k, item) in chunk.iter_mut().enumerate() {
            work(c * CHUNK + k, item);
        }
    };
    if threads <= 1 || count <= 1 {
        out.chunks_mut(CHUNK).enumerate().for_each(|(c, chunk)| run(c, chunk));
        return;
    }
    let queue = std::sync::Mutex::new(out.chunks_mut(CHUNK).enumerate());
    let worker = || {
        loop {
            let next = queue.lock().unwrap_or_else(std::sync::PoisonError::into_inner).next();
            let Some((c, chunk)) = next else { return };
            run(c, chunk);
        }
    };
    std::thread::scope(|s| {
        let helpers: Vec<_> = (1..threads.min(count)).map(|_| s.spawn(worker)).collect();
        worker();
        for h in helpers {
            h.join().unwrap_or_else(|e| std::panic::resume_unwind(e));
        }
    });
}

/// [`chunks`] whose results are lists, concatenated in order.
pub(crate) fn flat<T: Send>(threads: usize, n: usize, work: impl Fn(Range<usize>) -> Vec<T> + Sync) -> Vec<T> {
    chunks(threads, n, work).into_iter().flatten().collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn results_come_in_item_order_whatever_the_threads() {
        let square = |r: Range<usize>| r.map(|i| i * i).collect::<Vec<_>>();
        let expected: Vec<usize> = (0..1000).map(|i| i * i).collect();
        for t in [1, 2, 3, 8] {
            assert_eq!(flat(t, 1000, square), expected, "{t} threads");
        }
        assert!(flat(2, 0, square).is_empty());
        for t in [1, 2, 3, 8] {
            let mut out = vec![0; 1000];
            fill(t, &mut out, |i, o| *o = i * i);
            assert_eq!(out, expected, "{t} threads, in place");
        }
    }
}
