//! A bounding volume hierarchy over any list of boxes: the scene's objects, a mesh's
//! triangles. It is built once, top down, choosing each split by the surface area
//! heuristic over a few bins of box centres (Wald's binned build), and flattened into an
//! array whose nodes need no pointers. The items themselves stay with the caller, which
//! reorders them as [`Tree::build`] says so that every leaf covers a run of them.

use crate::bounds::Aabb;
use crate::ray::Ray;
use glam::DVec3;
use std::ops::Range;

/// Buckets of box centres along an axis in which split positions are compared.
const BINS: usize = 12;

/// What visiting a node costs, relative to testing one item, in the surface area heuristic.
const TRAVERSAL_COST: f64 = 0.5;

/// Below this depth splits follow the heuristic; deeper (rare, in lopsided scenes) they
/// halve the items, so that the depth stays within the traversal stack.
const HEURISTIC_DEPTH: usize = 64;

/// The deepest a node may be.
const MAX_DEPTH: usize = 120;

/// Nodes over at least this many items build their two subtrees at once, where threads
/// exist; smaller ones are not worth a thread's start.
const PARALLEL_ITEMS: usize = 4096;

/// The traversal stack of a tree up to this deep lives in the traversal's frame; a deeper
/// tree's is allocated. The stack holds one entry per level and one more, and a frame's
/// array is zeroed on every traversal, so it is no larger than most trees need.
const INLINE_STACK: usize = 48;

/// The stack of a shallow tree (the objects of most scenes), cheaper still to zero.
const SMALL_STACK: usize = 16;

#[derive(Debug, Clone, Copy, PartialEq)]
struct Node {
    bounds: Aabb,
    /// For a leaf, its first item; for an inner node, the second child's index (the first
    /// child follows the node directly).
    index: u32,
    /// Items in a leaf; 0 for an inner node.
    count: u32,
    /// The axis an inner node splits, which orders its children along a ray.
    axis: u8,
    /// The kinds of rays that see some item under the node (a set of
    /// [`RayKind::bit`](crate::ray::RayKind::bit)s): every kind until
    /// [`Tree::restrict_kinds`] says otherwise.
    kinds: u8,
}

/// The flattened hierarchy.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Tree {
    nodes: Vec<Node>,
    /// The deepest node's level, the root's being 0.
    depth: usize,
}

/// An item while the tree is built.
#[derive(Debug, Clone, Copy)]
struct Item {
    bounds: Aabb,
    centre: DVec3,
    index: u32,
}

/// How a node's items are divided.
enum Split {
    Leaf,
    /// The first `n` items (after partitioning) go left.
    At(usize),
}

impl Tree {
    /// The tree over `boxes` with leaves of at most `max_leaf` items, and the order the
    /// caller must put its items in: position `i` holds item `order[i]`.
    pub fn build(boxes: &[Aabb], max_leaf: usize) -> (Tree, Vec<u32>) {
        let mut items: Vec<Item> = boxes
            .iter()
            .enumerate()
            .map(|(i, b)| Item {
                bounds: *b,
                centre: b.centre(),
                index: i as u32,
            })
            .collect();
        let mut nodes = Vec::with_capacity((2 * items.len() / max_leaf.max(1)).max(1));
        let mut depth = 0;
        if !items.is_empty() {
            build_node(&mut items, 0, 0, max_leaf.max(1), &mut nodes, &mut depth);
        }
        let order = items.iter().map(|item| item.index).collect();
        (Tree { nodes, depth }, order)
    }

    /// Marks each node with the kinds of rays that see some item under it, given those of
    /// each item in the tree's order, so that [`Tree::traverse`] skips subtrees no ray of
    /// its kind sees (the scene's `no_shadow` objects, for shadow rays).
    pub fn restrict_kinds(&mut self, item_kinds: impl Fn(usize) -> u8) {
        // Children follow their parent, so going backwards meets them first.
        for i in (0..self.nodes.len()).rev() {
            let node = self.nodes[i];
            self.nodes[i].kinds = if node.count > 0 {
                let start = node.index as usize;
                (start..start + node.count as usize).fold(0, |set, item| set | item_kinds(item))
            } else {
                self.nodes[i + 1].kinds | self.nodes[node.index as usize].kinds
            };
        }
    }

    /// The box around every item; empty for an empty tree.
    pub fn bounds(&self) -> Aabb {
        self.nodes.first().map_or(Aabb::EMPTY, |n| n.bounds)
    }

    /// The bytes the nodes take.
    pub fn memory(&self) -> usize {
        self.nodes.len() * std::mem::size_of::<Node>()
    }

    /// Calls `visit` with the items of every leaf whose box the ray crosses within
    /// `[tmin, tmax]` and whose items rays of `kind` (a
    /// [`RayKind::bit`](crate::ray::RayKind::bit), or every bit for any ray) may see, the
    /// nearer child of each node first. `visit` returns the interval's new end (the
    /// nearest hit so far, for a nearest-hit search), which culls the leaves beyond it; an
    /// end before `tmin` stops the traversal (a search that found what it wanted).
    pub fn traverse(
        &self,
        ray: &Ray,
        inv_dir: DVec3,
        tmin: f64,
        tmax: f64,
        kind: u8,
        mut visit: impl FnMut(Range<usize>, f64) -> f64,
    ) {
        let Some(root) = self.nodes.first() else {
            return;
        };
        // A tree of one leaf (a scene of a few objects) needs no stack.
        if root.count > 0 {
            if root.kinds & kind != 0 && root.bounds.clip(ray, inv_dir, tmin, tmax).is_some() {
                let start = root.index as usize;
                visit(start..start + root.count as usize, tmax);
            }
            return;
        }
        if self.depth + 2 <= SMALL_STACK {
            self.walk(
                &mut [0; SMALL_STACK],
                ray,
                inv_dir,
                (tmin, tmax),
                kind,
                visit,
            );
        } else if self.depth + 2 <= INLINE_STACK {
            self.walk(
                &mut [0; INLINE_STACK],
                ray,
                inv_dir,
                (tmin, tmax),
                kind,
                visit,
            );
        } else {
            self.walk(
                &mut vec![0; self.depth + 2],
                ray,
                inv_dir,
                (tmin, tmax),
                kind,
                visit,
            );
        }
    }

    /// [`Tree::traverse`] with a stack of at least the depth plus two entries.
    #[inline]
    fn walk(
        &self,
        stack: &mut [u32],
        ray: &Ray,
        inv_dir: DVec3,
        (tmin, mut tmax): (f64, f64),
        kind: u8,
        mut visit: impl FnMut(Range<usize>, f64) -> f64,
    ) {
        let negative = [
            ray.direction.x < 0.0,
            ray.direction.y < 0.0,
            ray.direction.z < 0.0,
        ];
        stack[0] = 0;
        let mut top = 1;
        while top > 0 {
            top -= 1;
            let node = &self.nodes[stack[top] as usize];
            if node.kinds & kind == 0 || node.bounds.clip(ray, inv_dir, tmin, tmax).is_none() {
                continue;
            }
            if node.count > 0 {
                let start = node.index as usize;
                tmax = visit(start..start + node.count as usize, tmax);
                if tmax < tmin {
                    return;
                }
            } else {
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
    }
}

/// Builds the node for `items` (at `offset` in the final order) and its subtree.
fn build_node(
    items: &mut [Item],
    offset: usize,
    depth: usize,
    max_leaf: usize,
    nodes: &mut Vec<Node>,
    deepest: &mut usize,
) {
    *deepest = (*deepest).max(depth);
    let (mut bounds, mut centres) = (Aabb::EMPTY, Aabb::EMPTY);
    for item in items.iter() {
        bounds = bounds.union(&item.bounds);
        centres.min = centres.min.min(item.centre);
        centres.max = centres.max.max(item.centre);
    }
    let here = nodes.len();
    let (split, axis) = choose_split(items, &bounds, &centres, depth, max_leaf);
    let left = match split {
        Split::Leaf => {
            nodes.push(Node {
                bounds,
                index: offset as u32,
                count: items.len() as u32,
                axis: 0,
                kinds: u8::MAX,
            });
            return;
        }
        Split::At(left) => left,
    };
    nodes.push(Node {
        bounds,
        index: 0,
        count: 0,
        axis: axis as u8,
        kinds: u8::MAX,
    });
    let parallel = items.len() >= PARALLEL_ITEMS;
    let (near, far) = items.split_at_mut(left);
    if parallel {
        let ((near, near_depth), (far, far_depth)) = crate::parallel::join(
            || subtree(near, offset, depth + 1, max_leaf),
            || subtree(far, offset + left, depth + 1, max_leaf),
        );
        append(nodes, near);
        nodes[here].index = nodes.len() as u32;
        append(nodes, far);
        *deepest = (*deepest).max(near_depth).max(far_depth);
    } else {
        build_node(near, offset, depth + 1, max_leaf, nodes, deepest);
        nodes[here].index = nodes.len() as u32;
        build_node(far, offset + left, depth + 1, max_leaf, nodes, deepest);
    }
}

/// The nodes of the subtree over `items` on their own, numbered from 0, and its deepest
/// level: the same nodes [`build_node`] appends, up to the numbering.
fn subtree(items: &mut [Item], offset: usize, depth: usize, max_leaf: usize) -> (Vec<Node>, usize) {
    let mut nodes = Vec::with_capacity(2 * items.len() / max_leaf);
    let mut deepest = depth;
    build_node(items, offset, depth, max_leaf, &mut nodes, &mut deepest);
    (nodes, deepest)
}

/// Appends a subtree numbered from 0 to `nodes`, renumbering its inner nodes' links to
/// their second children; leaves keep their items' places, which are already final.
fn append(nodes: &mut Vec<Node>, subtree: Vec<Node>) {
    let base = nodes.len() as u32;
    nodes.extend(subtree.into_iter().map(|mut node| {
        if node.count == 0 {
            node.index += base;
        }
        node
    }));
}

/// Chooses how to divide `items` (within `bounds`, their centres within `centres`),
/// partitioning them in place when they are divided, and the axis of the division.
fn choose_split(
    items: &mut [Item],
    bounds: &Aabb,
    centres: &Aabb,
    depth: usize,
    max_leaf: usize,
) -> (Split, usize) {
    let n = items.len();
    if n <= 1 || depth >= MAX_DEPTH {
        return (Split::Leaf, 0);
    }
    let extent = centres.max - centres.min;
    let axis = longest_axis(extent);
    if extent[axis] <= 0.0 || !extent[axis].is_finite() {
        // Every centre coincides: only the count can divide them.
        return if n <= max_leaf {
            (Split::Leaf, 0)
        } else {
            (Split::At(n / 2), axis)
        };
    }
    if depth >= HEURISTIC_DEPTH {
        return (median_split(items, axis), axis);
    }
    let Some((cost, axis, bin)) = cheapest_bin(items, centres) else {
        return (median_split(items, axis), axis);
    };
    let area = surface_area(bounds);
    let leaf_cost = n as f64;
    let split_cost = TRAVERSAL_COST + cost / area.max(f64::MIN_POSITIVE);
    if n <= max_leaf && leaf_cost <= split_cost {
        return (Split::Leaf, 0);
    }
    let scale = BINS as f64 / (centres.max[axis] - centres.min[axis]);
    let min = centres.min[axis];
    let left = partition(items, |item| bin_of(item.centre[axis], min, scale) <= bin);
    if left == 0 || left == n {
        return (median_split(items, axis), axis);
    }
    (Split::At(left), axis)
}

/// The best split among the bins of all three axes: its cost (the sum over both sides of
/// area times count), its axis and the last bin of its left side. One pass over the items
/// fills the bins of every axis.
fn cheapest_bin(items: &[Item], centres: &Aabb) -> Option<(f64, usize, usize)> {
    let extent = centres.max - centres.min;
    let scale = DVec3::splat(BINS as f64) / extent;
    let mut counts = [[0usize; BINS]; 3];
    let mut boxes = [[Aabb::EMPTY; BINS]; 3];
    for item in items {
        for axis in 0..3 {
            if extent[axis] > 0.0 {
                let b = bin_of(item.centre[axis], centres.min[axis], scale[axis]);
                counts[axis][b] += 1;
                boxes[axis][b] = boxes[axis][b].union(&item.bounds);
            }
        }
    }
    let mut best: Option<(f64, usize, usize)> = None;
    for axis in 0..3 {
        if extent[axis] <= 0.0 {
            continue;
        }
        let (counts, boxes) = (&counts[axis], &boxes[axis]);
        // The cost of everything right of each boundary, swept from the right. An empty
        // bin changes neither side, so it costs no area: near the leaves, where a node
        // holds a few items, most bins are empty, and there are as many nodes as items.
        let mut right_cost = [0.0; BINS];
        let (mut area_box, mut count, mut cost) = (Aabb::EMPTY, 0, 0.0);
        for b in (1..BINS).rev() {
            if counts[b] > 0 {
                area_box = area_box.union(&boxes[b]);
                count += counts[b];
                cost = surface_area(&area_box) * count as f64;
            }
            right_cost[b] = cost;
        }
        let (mut left_box, mut left_count) = (Aabb::EMPTY, 0);
        for b in 0..BINS - 1 {
            // A boundary after an empty bin divides as the one before it does, at the
            // same cost, and the first of equal costs is kept.
            if counts[b] == 0 {
                continue;
            }
            left_box = left_box.union(&boxes[b]);
            left_count += counts[b];
            if left_count == 0 || left_count == items.len() {
                continue;
            }
            let cost = surface_area(&left_box) * left_count as f64 + right_cost[b + 1];
            if best.is_none_or(|(c, _, _)| cost < c) {
                best = Some((cost, axis, b));
            }
        }
    }
    best
}

fn bin_of(value: f64, min: f64, scale: f64) -> usize {
    (((value - min) * scale) as usize).min(BINS - 1)
}

/// Halves the items at the median centre along `axis`.
fn median_split(items: &mut [Item], axis: usize) -> Split {
    let mid = items.len() / 2;
    items.select_nth_unstable_by(mid, |a, b| a.centre[axis].total_cmp(&b.centre[axis]));
    Split::At(mid)
}

/// Moves the items for which `left` holds to the front; returns how many there are.
fn partition(items: &mut [Item], left: impl Fn(&Item) -> bool) -> usize {
    let mut first_right = 0;
    for i in 0..items.len() {
        if left(&items[i]) {
            items.swap(i, first_right);
            first_right += 1;
        }
    }
    first_right
}

fn longest_axis(extent: DVec3) -> usize {
    if extent.x >= extent.y && extent.x >= extent.z {
        0
    } else if extent.y >= extent.z {
        1
    } else {
        2
    }
}

fn surface_area(b: &Aabb) -> f64 {
    if b.is_empty() {
        return 0.0;
    }
    let d = b.max - b.min;
    2.0 * (d.x * d.y + d.y * d.z + d.z * d.x)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn unit_box(at: DVec3) -> Aabb {
        Aabb::new(at - DVec3::splat(0.5), at + DVec3::splat(0.5))
    }

    /// A hundred unit boxes in a row along +z, two units apart.
    fn boxes_along_z() -> Vec<Aabb> {
        (0..100)
            .map(|i| unit_box(DVec3::new(0.0, 0.0, 2.0 * i as f64)))
            .collect()
    }

    /// Traverses with rays of `kind` along +z from z = -5.
    fn along_z(tree: &Tree, kind: u8, visit: impl FnMut(Range<usize>, f64) -> f64) {
        let ray = Ray::new(DVec3::new(0.0, 0.0, -5.0), DVec3::Z);
        tree.traverse(&ray, ray.direction.recip(), 0.0, f64::INFINITY, kind, visit);
    }

    /// Every item the ray's box test admits, by brute force and through the tree.
    fn crossed(tree: &Tree, order: &[u32], boxes: &[Aabb], ray: &Ray) -> (Vec<u32>, Vec<u32>) {
        let inv = ray.direction.recip();
        let mut expected: Vec<u32> = (0..boxes.len() as u32)
            .filter(|&i| {
                boxes[i as usize]
                    .clip(ray, inv, 0.0, f64::INFINITY)
                    .is_some()
            })
            .collect();
        let mut found = Vec::new();
        tree.traverse(ray, inv, 0.0, f64::INFINITY, u8::MAX, |range, tmax| {
            for &i in &order[range] {
                if boxes[i as usize]
                    .clip(ray, inv, 0.0, f64::INFINITY)
                    .is_some()
                {
                    found.push(i);
                }
            }
            tmax
        });
        expected.sort_unstable();
        found.sort_unstable();
        (expected, found)
    }

    #[test]
    fn traversal_finds_what_brute_force_finds() {
        // A grid of boxes with a dense cluster in one corner, so that the heuristic
        // has lopsided splits to make.
        let mut boxes = Vec::new();
        for i in 0..20 {
            for j in 0..20 {
                boxes.push(unit_box(DVec3::new(i as f64 * 3.0, j as f64 * 3.0, 0.0)));
            }
        }
        for k in 0..200 {
            boxes.push(unit_box(DVec3::new(0.01 * k as f64, 0.0, 5.0)));
        }
        let (tree, order) = Tree::build(&boxes, 4);
        let mut sorted = order.clone();
        sorted.sort_unstable();
        assert_eq!(sorted, (0..boxes.len() as u32).collect::<Vec<_>>());
        for (origin, direction) in [
            (DVec3::new(-5.0, 3.0, 0.0), DVec3::X),
            (DVec3::new(-1.0, -1.0, -10.0), DVec3::new(0.1, 0.1, 1.0)),
            (DVec3::new(1.0, 0.0, -10.0), DVec3::Z),
        ] {
            let (expected, found) = crossed(&tree, &order, &boxes, &Ray::new(origin, direction));
            assert!(!expected.is_empty());
            assert_eq!(expected, found);
        }
    }

    /// Boxes at distances growing a hundredfold make every split peel the farthest off
    /// (all the others share the nearest bin): a tree deeper than the stack a traversal
    /// keeps in its frame, which then takes one from the heap.
    #[test]
    fn deep_trees_are_traversed_whole() {
        let boxes: Vec<Aabb> = (0..60)
            .map(|k| {
                let x = 100f64.powi(k);
                Aabb::new(
                    DVec3::new(0.75 * x, -0.5, -0.5),
                    DVec3::new(1.25 * x, 0.5, 0.5),
                )
            })
            .collect();
        let (tree, order) = Tree::build(&boxes, 1);
        assert!(tree.depth + 2 > INLINE_STACK, "{}", tree.depth);
        let ray = Ray::new(DVec3::new(-5.0, 0.1, 0.0), DVec3::X);
        let (expected, found) = crossed(&tree, &order, &boxes, &ray);
        assert_eq!(expected.len(), boxes.len());
        assert_eq!(expected, found);
    }

    #[test]
    fn traversal_skips_subtrees_no_ray_of_its_kind_sees() {
        // A row of boxes along z; only every tenth is seen by the second kind of ray.
        let boxes = boxes_along_z();
        let (mut tree, order) = Tree::build(&boxes, 2);
        let kinds = |item: u32| if item.is_multiple_of(10) { 0b11 } else { 0b01 };
        tree.restrict_kinds(|i| kinds(order[i]));
        let leaves = |kind: u8| {
            let mut items: Vec<u32> = Vec::new();
            let mut leaves = 0;
            along_z(&tree, kind, |range, tmax| {
                leaves += 1;
                items.extend(
                    order[range]
                        .iter()
                        .copied()
                        .filter(|&i| kinds(i) & kind != 0),
                );
                tmax
            });
            items.sort_unstable();
            (items, leaves)
        };
        let (all, all_leaves) = leaves(0b01);
        assert_eq!(all, (0..100).collect::<Vec<u32>>());
        let (tenths, tenth_leaves) = leaves(0b10);
        assert_eq!(tenths, (0..100).step_by(10).collect::<Vec<u32>>());
        // Only the leaves holding a tenth box are visited.
        assert!(
            tenth_leaves <= 10 && tenth_leaves < all_leaves,
            "{tenth_leaves}"
        );
        assert_eq!(leaves(0b100), (Vec::new(), 0));
    }

    #[test]
    fn coincident_boxes_still_make_small_leaves() {
        let boxes = vec![unit_box(DVec3::ZERO); 1000];
        let (tree, _) = Tree::build(&boxes, 4);
        assert!(tree.nodes.iter().all(|n| n.count <= 4));
        let mut seen = 0;
        along_z(&tree, u8::MAX, |range, tmax| {
            seen += range.len();
            tmax
        });
        assert_eq!(seen, 1000);
    }

    #[test]
    fn the_interval_end_culls_far_leaves() {
        let boxes = boxes_along_z();
        let (tree, order) = Tree::build(&boxes, 1);
        let mut visited = Vec::new();
        along_z(&tree, u8::MAX, |range, _| {
            visited.extend_from_slice(&order[range]);
            // The first box hit ends the search at its far side.
            5.5
        });
        assert_eq!(visited, vec![0]);
    }

    #[test]
    fn an_end_before_the_start_stops_the_traversal() {
        let boxes = boxes_along_z();
        let (tree, _) = Tree::build(&boxes, 1);
        let mut leaves = 0;
        along_z(&tree, u8::MAX, |_, _| {
            leaves += 1;
            f64::NEG_INFINITY
        });
        assert_eq!(leaves, 1);
    }

    /// Where the subtree at `at` ends, checking that every inner node's second child
    /// follows its first child's subtree, as a build one node after another lays it out,
    /// and that leaves take their items in order from `next`.
    fn preorder_end(tree: &Tree, at: usize, next: &mut u32) -> usize {
        let node = tree.nodes[at];
        if node.count > 0 {
            assert_eq!(node.index, *next, "leaf {at}");
            *next += node.count;
            return at + 1;
        }
        let first_end = preorder_end(tree, at + 1, next);
        assert_eq!(node.index as usize, first_end, "node {at}");
        preorder_end(tree, first_end, next)
    }

    #[test]
    fn a_large_tree_built_in_parallel_is_the_tree_built_in_order() {
        // Boxes scattered by a hash, many more than a node builds its subtrees at once for.
        let boxes: Vec<Aabb> = (0..20_000u64)
            .map(|i| {
                let h = i.wrapping_mul(0x9e37_79b9_7f4a_7c15);
                let coordinate = |shift: u32| ((h >> shift) & 0xffff) as f64 / 655.36;
                unit_box(DVec3::new(coordinate(0), coordinate(16), coordinate(32)))
            })
            .collect();
        let build_on = |threads: usize| {
            rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .expect("a thread pool")
                .install(|| Tree::build(&boxes, 2))
        };
        let (tree, order) = build_on(1);
        let mut next = 0;
        assert_eq!(preorder_end(&tree, 0, &mut next), tree.nodes.len());
        assert_eq!(next as usize, boxes.len());
        assert!(tree.depth > 10, "{}", tree.depth);
        assert!(build_on(4) == (tree, order));
    }
}
