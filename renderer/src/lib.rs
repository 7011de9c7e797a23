//! The Povrayst ray tracer: builds runtime shapes, materials, lights and acceleration
//! structures from an [`analysis::scene::Scene`] and traces them into an image.
