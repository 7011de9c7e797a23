//! A bounding volume hierarchy over the scene's bounded objects, built once before tracing:
//! binary, split at the centroid median of the longest axis, flattened into an array so
//! that traversal needs no pointers. Unbounded objects (planes and what contains them)
//! are kept beside it and tested for every ray.

use crate::bounds::Aabb;
use crate::object::{Hit, Object, Query};

const LEAF_SIZE: usize = 2;

#[derive(Debug, Clone)]
struct Node {
    bounds: Aabb,
    /// For a leaf, the first object index; for an inner node, the second child's index
    /// (the first child follows the node directly).
    index: u32,
    /// Objects in a leaf; 0 for an inner node.
    count: u32,
    axis: u8,
}

/// The scene's objects with their acceleration structure.
#[derive(Debug, Clone)]
pub struct Bvh {
    nodes: Vec<Node>,
    objects: Vec<Object>,
    unbounded: Vec<Object>,
}

impl Bvh {
    pub fn build(objects: Vec<Object>) -> Bvh {
        let (mut bounded, unbounded): (Vec<Object>, Vec<Object>) = objects
            .into_iter()
            .filter(|o| !o.bounds().is_empty())
            .partition(|o| o.bounds().is_finite());
        let mut nodes = Vec::with_capacity(bounded.len().max(1) * 2);
        if !bounded.is_empty() {
            let mut items: Vec<(Aabb, Object)> =
                bounded.drain(..).map(|o| (o.bounds(), o)).collect();
            build_node(&mut items[..], 0, &mut nodes);
            bounded = items.into_iter().map(|(_, o)| o).collect();
        }
        Bvh {
            nodes,
            objects: bounded,
            unbounded,
        }
    }

    /// Whether `p` is inside any object.
    pub fn contains(&self, p: glam::DVec3) -> bool {
        self.objects
            .iter()
            .chain(&self.unbounded)
            .any(|o| o.inside(p))
    }

    /// Whether some object is unbounded (a plane, say).
    pub fn has_unbounded(&self) -> bool {
        !self.unbounded.is_empty()
    }

    /// Bounds of every bounded object; empty when there is none.
    pub fn bounds(&self) -> Aabb {
        self.nodes.first().map_or(Aabb::EMPTY, |n| n.bounds)
    }

    /// The nearest crossing of any object inside the query's interval.
    pub fn nearest<'a>(&'a self, q: &Query, scratch: &mut Vec<Hit<'a>>) -> Option<Hit<'a>> {
        let mut q = *q;
        let mut best = None;
        for object in &self.unbounded {
            if let Some(hit) = object.nearest(&q, scratch) {
                q.tmax = hit.t;
                best = Some(hit);
            }
        }
        if self.nodes.is_empty() {
            return best;
        }
        let negative = [
            q.ray.direction.x < 0.0,
            q.ray.direction.y < 0.0,
            q.ray.direction.z < 0.0,
        ];
        let mut stack = [0u32; 64];
        let mut top = 1;
        while top > 0 {
            top -= 1;
            let node = &self.nodes[stack[top] as usize];
            if node
                .bounds
                .clip(&q.ray, q.inv_dir, q.tmin, q.tmax)
                .is_none()
            {
                continue;
            }
            if node.count > 0 {
                let start = node.index as usize;
                for object in &self.objects[start..start + node.count as usize] {
                    if let Some(hit) = object.nearest(&q, scratch) {
                        q.tmax = hit.t;
                        best = Some(hit);
                    }
                }
            } else if top + 2 <= stack.len() {
                // Visit the near child first so that the far one is often culled.
                let first = stack[top] + 1;
                let second = node.index;
                let (near, far) = if negative[node.axis as usize] {
                    (second, first)
                } else {
                    (first, second)
                };
                stack[top] = far;
                stack[top + 1] = near;
                top += 2;
            }
        }
        best
    }
}

fn build_node(items: &mut [(Aabb, Object)], offset: usize, nodes: &mut Vec<Node>) {
    let bounds = items.iter().fold(Aabb::EMPTY, |b, (ob, _)| b.union(ob));
    let here = nodes.len();
    if items.len() <= LEAF_SIZE {
        nodes.push(Node {
            bounds,
            index: offset as u32,
            count: items.len() as u32,
            axis: 0,
        });
        return;
    }
    let centroids = items.iter().fold(Aabb::EMPTY, |b, (ob, _)| {
        b.union(&Aabb::new(ob.centre(), ob.centre()))
    });
    let extent = centroids.max - centroids.min;
    let axis = if extent.x >= extent.y && extent.x >= extent.z {
        0
    } else if extent.y >= extent.z {
        1
    } else {
        2
    };
    let mid = items.len() / 2;
    items.select_nth_unstable_by(mid, |a, b| {
        a.0.centre()[axis].total_cmp(&b.0.centre()[axis])
    });
    nodes.push(Node {
        bounds,
        index: 0,
        count: 0,
        axis: axis as u8,
    });
    let (left, right) = items.split_at_mut(mid);
    build_node(left, offset, nodes);
    nodes[here].index = nodes.len() as u32;
    build_node(right, offset + mid, nodes);
}
