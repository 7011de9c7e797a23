//! What a CSG node knows of its children's insides along one ray. A convex child (a
//! sphere, a box, a closed cylinder or cone, a plane, inverted or not) is inside along one
//! stretch of the ray, found once from its own two crossings; whether a crossing of another
//! child lies inside it is then a comparison of ray parameters instead of a point test in
//! its frame. Other children are tested point by point. Stretches are found as they are
//! needed: an intersection first meets its uninverted convex children's, which often
//! settle the ray alone.

use crate::object::{Leaf, Object, Query};
use crate::ray::Ray;
use crate::shapes::{Root, Shape, Span};
use glam::DVec3;

/// How many children of one node keep their stretches; those after them (a difference of
/// many holes) are tested point by point, so that no node allocates per ray.
const HELD: usize = 8;

/// One child's inside along the ray.
#[derive(Debug, Clone, Copy)]
enum Along {
    /// Not looked at yet: tested at each point until it is.
    Unknown,
    /// Strictly between the span's ends, or outside them for an inverted child.
    Span { span: Span, inverse: bool },
    /// Tested at each point.
    Point,
}

/// The insides of a node's children along the ray of one query.
pub(crate) struct ChildSpans {
    along: [Along; HELD],
    /// Whether some child has not been looked at.
    pending: bool,
}

/// Where an intersection's uninverted convex children meet along the ray: every crossing
/// the intersection keeps lies in `[lo, hi]`, from the last of their entries to the first
/// of their exits.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Meeting {
    pub lo: f64,
    pub hi: f64,
    /// The one child that is not an uninverted convex leaf, if there is only one (a cubic
    /// clipped by a sphere): its crossings that the node keeps are those strictly inside
    /// the meeting.
    pub sole_other: Option<usize>,
    /// The child whose entry is the last (the first of them, should several enter there),
    /// with that crossing, when every child before it is an uninverted convex leaf: a
    /// crossing of no other child at the same parameter can then come before it.
    pub entry: Option<(usize, Root)>,
}

impl ChildSpans {
    /// Nothing looked at yet: every child is tested at each point until it is.
    pub fn new() -> ChildSpans {
        ChildSpans {
            along: [Along::Unknown; HELD],
            pending: true,
        }
    }

    /// The stretches of the uninverted leaves among the children and where they meet;
    /// `None` when they have no point in common within the query's interval, so that an
    /// intersection (or a clip) has no crossing there. The child `first` (the node's hull,
    /// a sphere or box holding its surface) is looked at first, so that a ray passing it
    /// by costs no other test.
    pub fn meet(
        &mut self,
        children: &[Object],
        q: &Query,
        first: Option<usize>,
    ) -> Option<Meeting> {
        let (mut lo, mut hi) = (f64::NEG_INFINITY, f64::INFINITY);
        let mut entry: Option<(usize, Root)> = None;
        let mut first_other = children.len();
        let mut others = 0;
        self.pending = false;
        for k in 0..children.len() {
            // `first`, then the others in order.
            let i = match first {
                Some(f) if k == 0 => f,
                Some(f) if k <= f => k - 1,
                _ => k,
            };
            let span = match &children[i] {
                Object::Leaf(leaf) if !leaf.inverse => leaf.span(&q.ray).ok_or(Along::Point),
                _ => Err(Along::Unknown),
            };
            let span = match span {
                Ok(span) => span,
                Err(along) => {
                    first_other = first_other.min(i);
                    others += 1;
                    self.pending |= matches!(along, Along::Unknown);
                    if let Some(slot) = self.along.get_mut(i) {
                        *slot = along;
                    }
                    continue;
                }
            };
            if span.enter.t > lo || (span.enter.t == lo && entry.is_some_and(|(e, _)| i < e)) {
                lo = span.enter.t;
                entry = Some((i, span.enter));
            }
            if span.exit.t < hi {
                hi = span.exit.t;
            }
            if lo > hi || lo >= q.tmax || hi <= q.tmin {
                // No point of the query's interval is left in every stretch.
                return None;
            }
            if let Some(slot) = self.along.get_mut(i) {
                *slot = Along::Span {
                    span,
                    inverse: false,
                };
            }
        }
        Some(Meeting {
            lo,
            hi,
            sole_other: (others == 1).then_some(first_other),
            entry: entry.filter(|&(i, _)| i < first_other && i < HELD),
        })
    }

    /// Looks at every child not looked at yet.
    pub fn complete(&mut self, children: &[Object], q: &Query) {
        if !self.pending {
            return;
        }
        self.pending = false;
        for (slot, child) in self.along.iter_mut().zip(children) {
            if let Along::Unknown = slot {
                *slot = along_child(child, q);
            }
        }
    }

    /// The stretch of child `i`, a leaf, whose two ends are then its only crossings with
    /// the ray; `None` when its crossings must be asked of it.
    pub fn span(&self, i: usize) -> Option<Span> {
        match self.along.get(i) {
            Some(Along::Span { span, .. }) => Some(*span),
            _ => None,
        }
    }

    /// Whether child `j` holds the point at parameter `t` of the ray. A parameter at an
    /// end of the child's stretch is another surface meeting the child's exactly (two
    /// faces in one plane): the point test decides there, as it did before stretches, so
    /// that such coincident faces render as they did.
    pub fn inside(&self, children: &[Object], j: usize, t: f64, ray: &Ray) -> bool {
        match self.along.get(j) {
            Some(Along::Span { span, inverse }) if t != span.enter.t && t != span.exit.t => {
                span.holds(t) != *inverse
            }
            _ => match &children[j] {
                Object::Leaf(leaf) => leaf_holds(leaf, ray.at(t)),
                child => child.inside(ray.at(t)),
            },
        }
    }
}

/// Whether the leaf holds the point. A finite convex leaf's inside lies in the box around
/// it: a point outside the box needs no test in the leaf's frame (most points of a drilled
/// cube's faces are far from most drills).
fn leaf_holds(leaf: &Leaf, p: DVec3) -> bool {
    let bounded = leaf.shape.has_convex_span() && !matches!(leaf.shape, Shape::Plane(_));
    if bounded && !(p.cmpge(leaf.bounds.min).all() && p.cmple(leaf.bounds.max).all()) {
        return leaf.inverse;
    }
    leaf.inside(p)
}

/// A child's inside along the query's ray: its stretch when it is a convex leaf (found as
/// cheaply as a test of the box around it would be), nowhere within the query's interval
/// for a CSG child whose inside the ray passes by there.
fn along_child(child: &Object, q: &Query) -> Along {
    match child {
        Object::Leaf(leaf) => leaf.span(&q.ray).map_or(Along::Point, |span| Along::Span {
            span,
            inverse: leaf.inverse,
        }),
        Object::Csg(csg)
            if csg.region.is_finite()
                && csg.region.clip(&q.ray, q.inv_dir, q.tmin, q.tmax).is_none() =>
        {
            Along::Span {
                span: Span::NOWHERE,
                inverse: false,
            }
        }
        Object::Csg(_) => Along::Point,
    }
}
