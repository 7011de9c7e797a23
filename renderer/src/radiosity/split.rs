//! A pretrace gather's rays shared with a free thread, with the results the rays would
//! have had on one. The pretrace's units are cut by ray counts alone, so one often ends
//! well before the other (on radiosity-emissive, the two units of a round took 8.6 and
//! 18.3 ms): the thread of a unit that has ended keeps taking up work (see
//! `parallel::help_until`) until the round's last unit ends, and the gathers of the units
//! still running offer it half of their rays.
//!
//! This tracer traces the first half of the rays while the free thread, if one takes it
//! up, traces the second on a copy of the tracer (a copy shares none of its own gathers
//! further). Rays that meet surfaces at the recursion limit take no samples and depend on
//! nothing before them, so the copy's rays are always those this tracer would have
//! traced. Rays below the limit may take samples, which the rays after them read: the
//! copy's rays count only if the first half took none, and their samples then join this
//! tracer's in the order it would have taken them; otherwise the second half is halved
//! again from where the first ended. After a gather whose rays took samples, the next
//! keeps its rays on this thread (their own gathers are still shared): while samples are
//! being taken, the copy's rays rarely count and keep the free thread from the gathers of
//! those samples. A tracer's other state (the blocker its last shadow ray met, the last
//! diffusion profile) changes how fast it finds results, never which; the photons found
//! near its last points could change their order, and gathers in scenes with photons stay
//! on one thread.

use super::gather::{GatherRays, Gathered};
use crate::parallel::join_helped;
use crate::tracer::Tracer;
use glam::DVec3;
use std::sync::atomic::{AtomicBool, Ordering};

/// The fewest rays worth handing to another thread: a copy of the tracer costs about as
/// much as a ray.
const FEWEST_SHARED: usize = 8;

/// How a shared gather's second half is run, if at all: by a free thread if one takes it
/// up while the first half is traced ([`ToAFreeThread`]). Whatever the answer and the
/// timing, the results are those of one thread; the tests run it always and never.
pub(super) trait Offer {
    /// Runs `mine`, and `theirs` if the offer is taken up: `None` when it is not, and then
    /// `theirs` does not run.
    fn join<A: Send, B: Send>(
        mine: impl FnOnce() -> A + Send,
        theirs: impl FnOnce() -> B + Send,
    ) -> (A, Option<B>);
}

/// The render's offer: to a thread whose own work has ended.
pub(super) struct ToAFreeThread;

impl Offer for ToAFreeThread {
    #[inline(always)]
    fn join<A: Send, B: Send>(
        mine: impl FnOnce() -> A + Send,
        theirs: impl FnOnce() -> B + Send,
    ) -> (A, Option<B>) {
        join_helped(mine, theirs)
    }
}

/// Set once the first half of a shared gather has taken a sample: the copy's rays no
/// longer count. On a cache line of its own, which the thread tracing the first half does
/// not write while it works.
#[derive(Default)]
#[repr(align(128))]
struct Sampled(AtomicBool);

impl<'w> Tracer<'w> {
    /// The light each of the gathering rays in `directions` brings back, in order, into
    /// `gathered`, with shares offered as `O` offers them: to a free thread in a render.
    pub(super) fn gather_shared<O: Offer>(
        &mut self,
        rays: &GatherRays,
        directions: &[DVec3],
        gathered: &mut Vec<Gathered>,
    ) {
        let mut next = 0;
        let before = self.own_count();
        let quiet = self.radiosity.as_ref().is_some_and(|w| w.quiet);
        while (!rays.sampling || quiet) && directions.len() - next >= 2 * FEWEST_SHARED {
            let middle = next + (directions.len() - next) / 2;
            let (mine, theirs) = (&directions[next..middle], &directions[middle..]);
            let walk = self.radiosity.as_ref().expect("a pretrace gather's walk");
            let lengths = walk.own_lengths();
            let copy = self.copy_with(walk.fork());
            let sampled = Sampled::default();
            let (took_samples, helped) = O::join(
                || {
                    let before = self.own_count();
                    for &d in mine {
                        gathered.push(self.gather_ray(rays, d));
                        if self.own_count() != before {
                            sampled.0.store(true, Ordering::Relaxed);
                        }
                    }
                    sampled.0.load(Ordering::Relaxed)
                },
                || {
                    // On this thread's own stack, away from the other thread's.
                    let mut copy = copy;
                    let mut light = Vec::with_capacity(theirs.len());
                    for &d in theirs {
                        if sampled.0.load(Ordering::Relaxed) {
                            return None;
                        }
                        light.push(copy.gather_ray(rays, d));
                    }
                    Some((light, copy.radiosity))
                },
            );
            if let Some(Some((light, Some(walk)))) = helped
                && !took_samples
            {
                gathered.extend(light);
                if let Some(own) = &mut self.radiosity {
                    own.adopt(walk, &lengths);
                }
                next = directions.len();
                break;
            }
            next = middle;
        }
        for &d in &directions[next..] {
            gathered.push(self.gather_ray(rays, d));
        }
        if rays.sampling {
            let quiet = self.own_count() == before;
            if let Some(walk) = &mut self.radiosity {
                walk.quiet = quiet;
            }
        }
    }

    /// How many samples this tracer's walk has taken.
    fn own_count(&self) -> usize {
        self.radiosity.as_ref().map_or(0, |w| w.own_count())
    }
}
