//! The renderer's prepared answers to `trace()` and `inside()`, kept for the objects a
//! scene asks about again. Scenes place things by tracing the same declared terrain in a
//! loop, hundreds of times; preparing the object (building a height field's or a mesh's
//! hierarchy) costs far more than one ray, so it is done once per object.

use super::Evaluator;
use crate::geometry::{InsideTest, Tracer};
use crate::scene::Object;
use std::rc::Rc;

/// How many objects keep their prepared queries. A scene that builds a new object for each
/// query (`trace(sphere { P, R }, ...)` in a loop) gains nothing from keeping them, and
/// holding a few bounds the memory they keep alive.
const KEPT_OBJECTS: usize = 4;

/// Prepared queries by object, the most recently used last.
#[derive(Default)]
pub struct ObjectQueries {
    entries: Vec<Entry>,
}

/// The queries prepared for one object. The object is held, so its address, by which it
/// is found, cannot be reused by another one while the entry lives.
struct Entry {
    object: Rc<Object>,
    tracer: Option<Rc<Tracer>>,
    inside: Option<InsideTest>,
}

impl ObjectQueries {
    /// The entry of `object`, made the most recently used, or a new one.
    fn entry(&mut self, object: &Rc<Object>) -> &mut Entry {
        match self
            .entries
            .iter()
            .position(|entry| Rc::ptr_eq(&entry.object, object))
        {
            Some(index) => {
                let entry = self.entries.remove(index);
                self.entries.push(entry);
            }
            None => {
                if self.entries.len() == KEPT_OBJECTS {
                    self.entries.remove(0);
                }
                self.entries.push(Entry {
                    object: object.clone(),
                    tracer: None,
                    inside: None,
                });
            }
        }
        self.entries
            .last_mut()
            .expect("an entry was just placed last")
    }
}

impl Evaluator<'_> {
    /// The renderer's tracer for `object`, prepared on its first use.
    pub(super) fn tracer_of(&mut self, object: &Rc<Object>) -> Result<Rc<Tracer>, String> {
        let entry = self.object_queries.entry(object);
        if let Some(tracer) = &entry.tracer {
            return Ok(tracer.clone());
        }
        let tracer = Rc::new(self.geometry.tracer(object)?);
        entry.tracer = Some(tracer.clone());
        Ok(tracer)
    }

    /// The renderer's inside test for `object`, prepared on its first use.
    pub(super) fn inside_test_of(&mut self, object: &Rc<Object>) -> Result<InsideTest, String> {
        let entry = self.object_queries.entry(object);
        if let Some(test) = &entry.inside {
            return Ok(test.clone());
        }
        let test = self.geometry.inside_test(object)?;
        entry.inside = Some(test.clone());
        Ok(test)
    }
}
