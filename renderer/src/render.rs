//! From a scene description and options to an image: builds the world, picks the pixels of
//! a partial render, samples them with the chosen antialiasing method (rows in parallel
//! natively, one after another on wasm32, with the same result), and encodes the colours
//! for the output file.

use crate::build::{BuildError, BuildSettings, build_world, camera_of};
use crate::colour::{Curve, EncodeTable, Sample};
use crate::image::Image;
use crate::mesh_camera::MeshRays;
use crate::options::{Extent, Gamma, RenderOptions};
use crate::output_values::Output;
use crate::parallel::map_indices;
use crate::radiosity;
use crate::sampling::{self, CompareCurve, Compared, Sampler, Subdivider};
use crate::tracer::Tracer;
use analysis::scene::{Origin, Scene};

/// Renders a scene. `Err` names a scene feature this renderer cannot draw yet.
pub fn render(scene: &Scene, options: &RenderOptions) -> Result<Image, BuildError> {
    render_with_warnings(scene, options).map(|(image, _)| image)
}

/// [`render`], with the warnings shapes raise about what the render found (POV-Ray's
/// warnings after a render, such as an isosurface's max_gradient), each with where the
/// scene wrote the shape.
pub fn render_with_warnings(
    scene: &Scene,
    options: &RenderOptions,
) -> Result<(Image, Vec<(String, Origin)>), BuildError> {
    let mut world = build_world(
        scene,
        BuildSettings {
            quality: options.quality,
            output_alpha: options.output_alpha,
            max_trace_level: options.max_trace_level,
        },
    )?;
    let camera = camera_of(scene)?;
    world.bvh.view_from(camera.view());
    let (width, height) = (options.width.max(1), options.height.max(1));
    let region = Region::from_options(options, width, height);
    let frame = radiosity::Frame {
        width,
        height,
        columns: (region.x0, region.x1),
        rows: (region.y0, region.y1),
        corners: options.antialias && options.aa_method == 2,
    };
    radiosity::pretrace(&mut world, &camera, &frame);
    let assumed_gamma = scene
        .settings
        .assumed_gamma
        .or_else(|| analysis::scene::default_assumed_gamma(scene.version));
    let working = match assumed_gamma {
        Some(g) => Curve::from_gamma(Gamma::Power(g)),
        None => Curve::Identity,
    };
    let sampler = Sampler {
        world: &world,
        camera: &camera,
        width: f64::from(width),
        height: f64::from(height),
        threshold: options.aa_threshold,
        depth: options.aa_depth.clamp(1, 9),
        jitter: options.jitter_amount().max(0.0),
        compare: CompareCurve {
            working,
            // Without antialiasing no samples are compared, and the table (thousands of
            // powers, a fixed cost of every render) is not built.
            aa: EncodeTable::new(if options.antialias {
                Curve::Power(options.aa_gamma.unwrap_or(2.5))
            } else {
                Curve::Identity
            }),
        },
    };
    let samples = if let Some(mesh) = camera.mesh() {
        mesh_pixels(&sampler, mesh, &region)
    } else if !options.antialias {
        centres(&sampler, &region)
    } else {
        match options.aa_method {
            1 => method1(&sampler, &region),
            3 => method3(&sampler, &region, options.aa_confidence.unwrap_or(0.9)),
            _ => method2(&sampler, &region),
        }
    };
    let output = Output {
        legacy: assumed_gamma.is_none(),
        working,
        file: Curve::from_gamma(options.file_gamma.unwrap_or(Gamma::Srgb)),
        alpha: options.output_alpha,
    };
    let mut image = Image::new(width, height, options.output_alpha);
    output.write(
        &samples,
        &mut image,
        (region.x0 as usize, region.y0 as usize),
    );
    let warnings = world
        .shape_reports
        .iter()
        .filter_map(|r| r.message().map(|m| (m, r.origin.clone())))
        .collect();
    Ok((image, warnings))
}

/// The inclusive pixel rectangle a partial render covers.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Region {
    x0: u32,
    x1: u32,
    y0: u32,
    y1: u32,
}

impl Region {
    fn from_options(options: &RenderOptions, width: u32, height: u32) -> Region {
        let bound =
            |e: Option<Extent>, size: u32, default: u32| e.map_or(default, |e| e.resolve(size));
        let x0 = bound(options.start_column, width, 0);
        let x1 = bound(options.end_column, width, width - 1).max(x0);
        let y0 = bound(options.start_row, height, 0);
        let y1 = bound(options.end_row, height, height - 1).max(y0);
        Region { x0, x1, y0, y1 }
    }

    fn columns(&self) -> usize {
        (self.x1 - self.x0 + 1) as usize
    }
}

/// Rows antialiasing method 2 traces one after another, sharing the samples on the
/// edges between them; more rows share more, fewer leave more runs to trace in parallel.
/// On wasm32 (one thread) every row is in one run.
const SHARED_ROWS: usize = if cfg!(target_arch = "wasm32") {
    usize::MAX
} else {
    8
};

/// One ray through each pixel centre.
fn centres(sampler: &Sampler<'_>, region: &Region) -> Vec<Vec<Sample>> {
    map_indices((region.y1 - region.y0 + 1) as usize, |row| {
        let mut tracer = Tracer::new(sampler.world);
        let y = f64::from(region.y0) + row as f64 + 0.5;
        let points: Vec<(f64, f64)> = (region.x0..=region.x1)
            .map(|x| (f64::from(x) + 0.5, y))
            .collect();
        let mut samples = Vec::with_capacity(points.len());
        sampler.trace_all(&mut tracer, &points, &mut samples);
        samples
    })
}

/// Each pixel from its rays through a mesh camera, which do not depend on where in the
/// pixel it is sampled: there is nothing for antialiasing to refine.
fn mesh_pixels(sampler: &Sampler<'_>, mesh: &MeshRays, region: &Region) -> Vec<Vec<Sample>> {
    map_indices((region.y1 - region.y0 + 1) as usize, |row| {
        let mut tracer = Tracer::new(sampler.world);
        let y = f64::from(region.y0) + row as f64 + 0.5;
        (region.x0..=region.x1)
            .map(|x| sampler.mesh_pixel(&mut tracer, mesh, f64::from(x) + 0.5, y))
            .collect()
    })
}

fn method1(sampler: &Sampler<'_>, region: &Region) -> Vec<Vec<Sample>> {
    let centres = centres(sampler, region);
    let rows = centres.len();
    let cols = region.columns();
    map_indices(rows, |row| {
        let mut tracer = Tracer::new(sampler.world);
        // The row's supersampled pixels, and their grids' positions in one batch.
        let mut positions = Vec::new();
        let split: Vec<usize> = (0..cols)
            .filter(|&col| {
                let c = centres[row][col];
                let mut neighbours = [c; 4];
                if col > 0 {
                    neighbours[0] = centres[row][col - 1];
                }
                if col + 1 < cols {
                    neighbours[1] = centres[row][col + 1];
                }
                if row > 0 {
                    neighbours[2] = centres[row - 1][col];
                }
                if row + 1 < rows {
                    neighbours[3] = centres[row + 1][col];
                }
                sampling::needs_supersampling(sampler, c, &neighbours)
            })
            .inspect(|&col| {
                let (x, y) = (region.x0 + col as u32, region.y0 + row as u32);
                positions.extend(sampling::grid_positions(sampler, x, y));
            })
            .collect();
        let mut samples = Vec::with_capacity(positions.len());
        sampler.trace_all(&mut tracer, &positions, &mut samples);
        let mut pixels = centres[row].clone();
        let per_pixel = sampling::grid_points(sampler);
        for (&col, grid) in split.iter().zip(samples.chunks(per_pixel)) {
            pixels[col] = sampling::grid_mean(pixels[col], grid);
        }
        pixels
    })
}

fn method3(sampler: &Sampler<'_>, region: &Region, confidence: f64) -> Vec<Vec<Sample>> {
    let first = centres(sampler, region);
    let rows = first.len();
    let cols = region.columns();
    map_indices(rows, |row| {
        let mut tracer = Tracer::new(sampler.world);
        (0..cols)
            .map(|col| {
                let mut neighbours = Vec::with_capacity(4);
                if col > 0 {
                    neighbours.push(first[row][col - 1]);
                }
                if col + 1 < cols {
                    neighbours.push(first[row][col + 1]);
                }
                if row > 0 {
                    neighbours.push(first[row - 1][col]);
                }
                if row + 1 < rows {
                    neighbours.push(first[row + 1][col]);
                }
                let x = region.x0 + col as u32;
                let y = region.y0 + row as u32;
                sampling::stochastic_pixel(
                    sampler,
                    &mut tracer,
                    x,
                    y,
                    first[row][col],
                    &neighbours,
                    confidence,
                )
            })
            .collect()
    })
}

fn method2(sampler: &Sampler<'_>, region: &Region) -> Vec<Vec<Sample>> {
    let corner_rows = (region.y1 - region.y0 + 2) as usize;
    let corners: Vec<Vec<Compared>> = map_indices(corner_rows, |row| {
        let mut tracer = Tracer::new(sampler.world);
        let y = f64::from(region.y0) + row as f64;
        let points: Vec<(f64, f64)> = (region.x0..=region.x1 + 1)
            .map(|x| (f64::from(x), y))
            .collect();
        let mut samples = Vec::with_capacity(points.len());
        sampler.trace_all(&mut tracer, &points, &mut samples);
        samples.into_iter().map(|s| sampler.compared(s)).collect()
    });
    // Runs of rows share their subdividers, which keep the samples on the edges between
    // them from row to row; the runs are traced in parallel where threads exist. A wide
    // picture subdivided deeply goes down each run in strips of columns, which a
    // subdivider holds one at a time.
    let rows = corner_rows - 1;
    let columns = region.columns();
    let strip = Subdivider::columns_held(sampler.depth);
    let runs = map_indices(rows.div_ceil(SHARED_ROWS), |run| {
        let mut tracer = Tracer::new(sampler.world);
        let run_rows = run * SHARED_ROWS..(run + 1).saturating_mul(SHARED_ROWS).min(rows);
        let mut pixels = vec![vec![Sample::default(); columns]; run_rows.len()];
        for first in (0..columns).step_by(strip) {
            let end = (first + strip).min(columns);
            let mut subdivider = Subdivider::new(sampler, end - first);
            for (row, out) in run_rows.clone().zip(&mut pixels) {
                subdivider.row(
                    sampler,
                    &mut tracer,
                    (region.x0 + first as u32, region.y0 + row as u32),
                    [&corners[row][first..=end], &corners[row + 1][first..=end]],
                    &mut out[first..end],
                );
            }
        }
        pixels
    });
    runs.into_iter().flatten().collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::camera::Camera;
    use crate::tracer::World;
    use analysis::scene::{self, Colour, Finish, Light, Object, Pigment, Shape, Texture};
    use glam::DVec3;
    use std::sync::Arc;

    fn texture(rgb: DVec3) -> Option<Arc<Texture>> {
        Some(Arc::new(Texture::Plain {
            pigment: Pigment::Solid(Colour {
                rgb,
                filter: 0.0,
                transmit: 0.0,
            }),
            normal: None,
            finish: Arc::new(Finish::default()),
        }))
    }

    fn scene_of(objects: Vec<Object>) -> Scene {
        Scene {
            camera: scene::Camera {
                location: DVec3::new(0.0, 0.0, -60.0),
                direction: DVec3::Z * 1.5,
                ..scene::Camera::default()
            },
            lights: vec![Light::point(
                DVec3::new(0.0, 0.0, -100.0),
                Colour::gray(1.0),
            )],
            objects,
            background: Some(Colour::rgb(0.0, 0.0, 1.0)),
            fogs: Vec::new(),
            rainbows: Vec::new(),
            sky_sphere: None,
            media: Vec::new(),
            settings: Default::default(),
            version: Some(3.7),
        }
    }

    /// An orange sphere filling the middle of the picture.
    fn orange_sphere() -> Scene {
        let mut sphere = Object::new(
            Shape::Sphere {
                center: DVec3::ZERO,
                radius: 15.0,
            },
            None,
        );
        sphere.texture = texture(DVec3::new(0.8, 0.5, 0.2));
        scene_of(vec![sphere])
    }

    #[test]
    fn a_hundred_thousand_objects_render() {
        // A 100 x 100 x 10 block of small red spheres in front of a blue background.
        let red = texture(DVec3::new(1.0, 0.0, 0.0));
        let mut objects = Vec::with_capacity(100_000);
        for i in 0..100_000 {
            let (x, y, z) = (i % 100, (i / 100) % 100, i / 10_000);
            let mut o = Object::new(
                Shape::Sphere {
                    center: DVec3::new(f64::from(x) - 49.5, f64::from(y) - 49.5, f64::from(z))
                        * 0.4,
                    radius: 0.25,
                },
                None,
            );
            o.texture = red.clone();
            objects.push(o);
        }
        let options = RenderOptions {
            width: 40,
            height: 30,
            antialias: false,
            ..RenderOptions::default()
        };
        let image = render(&scene_of(objects), &options).unwrap();
        // The centre sees spheres, the corners see the background past the block.
        let centre = image.pixel(20, 15);
        assert!(centre[0] > 0.1 && centre[2] == 0.0, "{centre:?}");
        let corner = image.pixel(0, 0);
        assert!(corner[2] > 0.9 && corner[0] == 0.0, "{corner:?}");
    }

    #[test]
    fn degenerate_rays_and_shapes_give_no_nan() {
        // Grazing and coincident surfaces, a sphere at the camera, a huge and a tiny sphere.
        let objects = vec![
            Object::new(
                Shape::Plane {
                    normal: DVec3::Y,
                    distance: 0.0,
                },
                None,
            ),
            Object::new(
                Shape::Plane {
                    normal: DVec3::Y,
                    distance: 0.0,
                },
                None,
            ),
            Object::new(
                Shape::Sphere {
                    center: DVec3::new(0.0, 0.0, -60.0),
                    radius: 1.0,
                },
                None,
            ),
            Object::new(
                Shape::Sphere {
                    center: DVec3::ZERO,
                    radius: 1e-12,
                },
                None,
            ),
            Object::new(
                Shape::Sphere {
                    center: DVec3::ZERO,
                    radius: 1e12,
                },
                None,
            ),
            Object::new(
                Shape::Cone {
                    base: DVec3::ZERO,
                    base_radius: 0.0,
                    cap: DVec3::Y,
                    cap_radius: 0.0,
                    open: false,
                },
                None,
            ),
        ];
        let mut objects = objects;
        for o in &mut objects {
            o.texture = texture(DVec3::ONE);
        }
        let scene = scene_of(objects);
        let world = build_world(
            &scene,
            BuildSettings {
                quality: 9,
                output_alpha: true,
                max_trace_level: None,
            },
        )
        .unwrap();
        let camera = Camera::from_scene(&scene.camera).unwrap();
        let mut tracer = Tracer::new(&world);
        // Samples before output encoding, which would hide a NaN, over a fine grid that
        // includes rays grazing the coincident floors.
        for j in 0..=64 {
            for i in 0..=64 {
                let (x, y) = (f64::from(i) / 64.0 * 24.0, f64::from(j) / 64.0 * 18.0);
                if let Some(ray) = camera.ray(x, y, 24.0, 18.0) {
                    let s = tracer.trace_primary(&ray);
                    assert!(
                        s.colour.is_finite() && s.transmit.is_finite(),
                        "{x} {y}: {s:?}"
                    );
                }
            }
        }
    }

    /// The orange sphere's world, at full quality, and camera.
    fn orange_sphere_world() -> (World, Camera) {
        let scene = orange_sphere();
        let settings = BuildSettings {
            quality: 9,
            output_alpha: false,
            max_trace_level: None,
        };
        let world = build_world(&scene, settings).unwrap();
        (world, Camera::from_scene(&scene.camera).unwrap())
    }

    fn whole_picture(width: u32, height: u32) -> Region {
        Region {
            x0: 0,
            x1: width - 1,
            y0: 0,
            y1: height - 1,
        }
    }

    /// A sampler of a `width` × `height` picture, with full jitter.
    fn test_sampler<'a>(
        (world, camera): &'a (World, Camera),
        (width, height): (u32, u32),
        threshold: f64,
        depth: u32,
    ) -> Sampler<'a> {
        Sampler {
            world,
            camera,
            width: f64::from(width),
            height: f64::from(height),
            threshold,
            depth,
            jitter: 1.0,
            compare: CompareCurve {
                working: Curve::Identity,
                aa: EncodeTable::new(Curve::Power(2.5)),
            },
        }
    }

    #[test]
    fn pixels_sharing_edge_samples_match_pixels_sampled_alone() {
        let scene = orange_sphere_world();
        let (width, height) = (24, 18);
        let region = whole_picture(width, height);
        // A threshold of 0 splits every pixel down to the last level, so that every edge
        // sample is shared.
        let sampler = test_sampler(&scene, (width, height), 0.0, 3);
        let shared = method2(&sampler, &region);
        let mut tracer = Tracer::new(&scene.0);
        let mut corner = |x: u32, y: u32| {
            sampler.compared(sampler.trace(&mut tracer, f64::from(x), f64::from(y)))
        };
        for y in 0..height {
            for x in 0..width {
                let c = [
                    corner(x, y),
                    corner(x + 1, y),
                    corner(x, y + 1),
                    corner(x + 1, y + 1),
                ];
                let mut alone = [Sample::default()];
                Subdivider::new(&sampler, 1).row(
                    &sampler,
                    &mut Tracer::new(&scene.0),
                    (x, y),
                    [&c[..2], &c[2..]],
                    &mut alone,
                );
                assert_eq!(shared[y as usize][x as usize], alone[0], "{x} {y}");
            }
        }
    }

    /// Method 2's pixel `(x, y)` as one square after another traces it, one sample at a
    /// time: each square traces all its corners when it needs them.
    fn subdivided_one_at_a_time(sampler: &Sampler<'_>, (x, y): (u32, u32)) -> Sample {
        fn square(
            sampler: &Sampler<'_>,
            at: &mut impl FnMut(u32, u32) -> Sample,
            (bx, by): (u32, u32),
            step: u32,
            level: u32,
        ) -> Sample {
            let c = [
                at(bx, by),
                at(bx + step, by),
                at(bx, by + step),
                at(bx + step, by + step),
            ];
            let compared = c.map(|s| sampler.compare.apply(s));
            let differ = (0..4).any(|i| {
                (i + 1..4).any(|j| compared[i].distance(compared[j]) >= sampler.threshold)
            });
            if level == 0 || step < 2 || !differ {
                return (c[0] + c[1] + c[2] + c[3]) * 0.25;
            }
            let half = step / 2;
            let mut sum = Sample::default();
            for quarter in [
                (bx, by),
                (bx + half, by),
                (bx, by + half),
                (bx + half, by + half),
            ] {
                sum = sum + square(sampler, at, quarter, half, level - 1);
            }
            sum * 0.25
        }
        let mut tracer = Tracer::new(sampler.world);
        let last = 1 << (sampler.depth - 1);
        let unit = 1.0 / f64::from(last);
        let scale = sampler.jitter / f64::from((1 << sampler.depth) + 1);
        let mut at = |gx: u32, gy: u32| {
            let px = f64::from(x) + f64::from(gx) * unit;
            let py = f64::from(y) + f64::from(gy) * unit;
            // The pixel's corners are traced where they lie, the other points jittered.
            let (px, py) = if gx.is_multiple_of(last) && gy.is_multiple_of(last) {
                (px, py)
            } else {
                sampler.jittered(px, py, scale)
            };
            sampler.trace(&mut tracer, px, py)
        };
        square(sampler, &mut at, (0, 0), last, sampler.depth - 1)
    }

    #[test]
    fn subdivision_in_rounds_takes_the_samples_of_one_at_a_time() {
        let scene = orange_sphere_world();
        // The sphere's outline splits pixels to different depths. At depth 7 a subdivider
        // holds 31 columns, so that the 40 of the picture are sampled in two strips.
        assert_eq!(Subdivider::columns_held(7), 31);
        for (size, depth) in [((24, 18), 4), ((40, 30), 7)] {
            let region = Region {
                x0: 0,
                x1: size.0 - 1,
                y0: size.1 / 2 - 3,
                y1: size.1 / 2 + 2,
            };
            let sampler = test_sampler(&scene, size, 0.1, depth);
            let batched = method2(&sampler, &region);
            for y in region.y0..=region.y1 {
                for x in region.x0..=region.x1 {
                    let alone = subdivided_one_at_a_time(&sampler, (x, y));
                    let row = &batched[(y - region.y0) as usize];
                    assert_eq!(row[x as usize], alone, "depth {depth}: {x} {y}");
                }
            }
        }
    }

    /// Method 1 traces a row's supersampling grids in one batch: each pixel is still its
    /// centre averaged with its grid's samples, each traced alone at its jittered position.
    #[test]
    fn method_one_grids_in_a_batch_take_the_samples_of_one_at_a_time() {
        let scene = orange_sphere_world();
        let (width, height) = (24, 18);
        let region = whole_picture(width, height);
        let sampler = test_sampler(&scene, (width, height), 0.1, 3);
        let batched = method1(&sampler, &region);
        let centres = centres(&sampler, &region);
        let mut tracer = Tracer::new(&scene.0);
        let mut split = 0;
        for y in 0..height {
            for x in 0..width {
                let centre = centres[y as usize][x as usize];
                let pixel = batched[y as usize][x as usize];
                if pixel == centre {
                    continue;
                }
                split += 1;
                let grid: Vec<Sample> = sampling::grid_positions(&sampler, x, y)
                    .map(|(px, py)| sampler.trace(&mut tracer, px, py))
                    .collect();
                assert_eq!(grid.len(), 9);
                assert_eq!(pixel, sampling::grid_mean(centre, &grid), "{x} {y}");
            }
        }
        assert!(split > 20, "{split} pixels supersampled");
    }

    #[test]
    fn partial_renders_match_the_full_render_where_they_draw() {
        let scene = orange_sphere();
        let full_options = RenderOptions {
            width: 32,
            height: 24,
            ..RenderOptions::default()
        };
        let full = render(&scene, &full_options).unwrap();
        let mut partial_options = full_options.clone();
        for option in ["+SR0.5", "+ER20", "+SC5", "+EC0.75"] {
            partial_options.apply_povray_option(option).unwrap();
        }
        let partial = render(&scene, &partial_options).unwrap();
        for y in 0..24 {
            for x in 0..32 {
                let inside = (12..=19).contains(&y) && (4..=24).contains(&x);
                if inside {
                    assert_eq!(partial.pixel(x, y), full.pixel(x, y), "{x} {y}");
                } else {
                    assert_eq!(partial.pixel(x, y), [0.0, 0.0, 0.0, 1.0], "{x} {y}");
                }
            }
        }
    }

    #[test]
    fn scenes_of_3_7_without_assumed_gamma_take_1() {
        // POV-Ray 3.7 gives a `#version 3.7` scene without assumed_gamma 1.0 (with a
        // warning), so its render is that of the scene with `assumed_gamma 1`.
        let options = RenderOptions {
            width: 8,
            height: 6,
            antialias: false,
            ..RenderOptions::default()
        };
        let unset = render(&orange_sphere(), &options).unwrap();
        let mut one = orange_sphere();
        one.settings.assumed_gamma = Some(1.0);
        let one = render(&one, &options).unwrap();
        assert_eq!(unset.pixel(4, 3), one.pixel(4, 3));
        assert!(unset.pixel(4, 3)[2] > 0.3, "{:?}", unset.pixel(4, 3));
    }

    #[test]
    fn low_quality_shows_pigments_under_full_ambient() {
        // A legacy scene (no #version, no assumed_gamma): gamma is off.
        let scene = Scene {
            version: None,
            ..orange_sphere()
        };
        let options = RenderOptions {
            width: 8,
            height: 6,
            antialias: false,
            quality: 1,
            ..RenderOptions::default()
        };
        let image = render(&scene, &options).unwrap();
        // The pigment as it is.
        assert_eq!(image.pixel(4, 3), [0.8, 0.5, 0.2, 1.0]);
    }
}
