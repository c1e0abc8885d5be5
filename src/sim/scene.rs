//! Scenes: the serialisable description of the tabletop (objects, poses, the held object, the
//! camera and the step counter), saved and loaded as JSON.
//!
//! Invariants: a `Scene` that passed `validate` has unique, well-formed object names distinct
//! from `table` and the robot, finite poses with unit quaternions, and an `in_hand` that names
//! one of its objects. The scene is the source of truth between calls; a physics `World` is
//! built from it and written back into it. The table top is the plane y = 0, y points up.

use super::object::{Colour, ObjectKind, Size, Surface};
use super::SimError;
use parry3d::math::{Pose, Rot3, Vector};
use serde::{Deserialize, Serialize};

/// Half extents of the table top in metres (x, y, z); its top face is at y = 0.
pub const TABLE_HALF_EXTENTS: [f32; 3] = [0.6, 0.02, 0.45];

/// The name of the table as a location constant.
pub const TABLE: &str = "table";

/// The default robot constant.
pub const ROBOT: &str = "rob1";

/// A dense index of an object in `Scene::objects`; stable while the scene's object list is.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct ObjectId(pub u32);

impl ObjectId {
    /// The index into `Scene::objects`.
    pub fn index(self) -> usize {
        self.0 as usize
    }
}

/// One movable object of a scene.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct SceneObject {
    /// The constant naming the object in programs, e.g. `red_cube`.
    pub name: String,
    /// What the object is; fixes its shape and top surface.
    pub kind: ObjectKind,
    /// Its colour.
    pub colour: Colour,
    /// Its size class.
    pub size: Size,
    /// Position of the body origin in metres (x, y, z).
    pub position: [f32; 3],
    /// Orientation as a unit quaternion (x, y, z, w).
    pub rotation: [f32; 4],
}

impl SceneObject {
    /// The top surface, which follows from the kind.
    pub fn surface(&self) -> Surface {
        self.kind.surface()
    }

    /// The object's pose as a parry/rapier `Pose` (glam-based in this rapier version).
    pub fn pose(&self) -> Pose {
        let [x, y, z] = self.position;
        let [qx, qy, qz, qw] = self.rotation;
        Pose::from_parts(
            Vector::new(x, y, z),
            Rot3::from_xyzw(qx, qy, qz, qw).normalize(),
        )
    }

    /// Stores a pose into the object.
    pub fn set_pose(&mut self, pose: &Pose) {
        let t = pose.translation;
        let q = pose.rotation;
        self.position = [t.x, t.y, t.z];
        self.rotation = [q.x, q.y, q.z, q.w];
    }
}

/// A pinhole camera looking at the table.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Camera {
    /// Eye position in metres.
    pub eye: [f32; 3],
    /// The point looked at.
    pub target: [f32; 3],
    /// Vertical field of view in degrees.
    pub fov_y_degrees: f32,
}

impl Default for Camera {
    /// The robot's camera: on the robot's side of the table (negative z), above it, looking
    /// along +z and down at the middle of the table.
    fn default() -> Self {
        Camera {
            eye: [0.0, 0.5, -0.7],
            target: [0.0, 0.0, 0.06],
            fov_y_degrees: 44.0,
        }
    }
}

impl Camera {
    /// The eye as a vector.
    pub fn eye(&self) -> Vector {
        Vector::from_array(self.eye)
    }

    /// Unit viewing direction.
    pub fn forward(&self) -> Vector {
        (Vector::from_array(self.target) - self.eye()).normalize()
    }

    /// Unit vector pointing to the camera's right, parallel to the table.
    pub fn right(&self) -> Vector {
        self.forward().cross(Vector::Y).normalize()
    }

    /// Unit vector pointing up in the image.
    pub fn up(&self) -> Vector {
        self.right().cross(self.forward())
    }

    /// Unit depth direction parallel to the table: "in front" means smaller along it.
    pub fn depth_axis(&self) -> Vector {
        let f = self.forward();
        Vector::new(f.x, 0.0, f.z).normalize()
    }
}

/// A tabletop scene.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Scene {
    /// The seed the scene was generated from; observation noise and action failures at each
    /// step are drawn from streams derived from it and the step.
    pub seed: u64,
    /// The preset the scene was generated from, or `custom` for hand-built scenes.
    pub preset: String,
    /// The robot constant.
    #[serde(default = "default_robot")]
    pub robot: String,
    /// The current time step; every executed action advances it by one.
    #[serde(default)]
    pub step: u32,
    /// The object the robot holds, if any; a held object takes no part in the physics.
    #[serde(default)]
    pub in_hand: Option<String>,
    /// The robot's camera.
    #[serde(default)]
    pub camera: Camera,
    /// The movable objects.
    pub objects: Vec<SceneObject>,
}

fn default_robot() -> String {
    ROBOT.to_string()
}

impl Scene {
    /// An empty hand-built scene with the default robot and camera.
    pub fn custom(seed: u64) -> Self {
        Scene {
            seed,
            preset: "custom".to_string(),
            robot: default_robot(),
            step: 0,
            in_hand: None,
            camera: Camera::default(),
            objects: Vec::new(),
        }
    }

    /// Adds an object at a position, upright with a yaw in radians; returns its id.
    /// Panics on a duplicate name, which is API misuse in hand-built scenes.
    pub fn add(
        &mut self,
        name: &str,
        kind: ObjectKind,
        colour: Colour,
        size: Size,
        position: [f32; 3],
        yaw: f32,
    ) -> ObjectId {
        assert!(
            self.find(name).is_none(),
            "object `{name}` is already in the scene"
        );
        let q = Rot3::from_rotation_y(yaw);
        self.objects.push(SceneObject {
            name: name.to_string(),
            kind,
            colour,
            size,
            position,
            rotation: [q.x, q.y, q.z, q.w],
        });
        ObjectId(self.objects.len() as u32 - 1)
    }

    /// Adds an object resting with its lowest point at height `bottom` above (x, z), upright.
    pub fn add_resting(
        &mut self,
        name: &str,
        kind: ObjectKind,
        colour: Colour,
        size: Size,
        (x, bottom, z): (f32, f32, f32),
    ) -> ObjectId {
        let lowest = kind.shape(size).compute_local_aabb().mins.y;
        self.add(name, kind, colour, size, [x, bottom - lowest, z], 0.0)
    }

    /// The id of the object with this name.
    pub fn find(&self, name: &str) -> Option<ObjectId> {
        self.objects
            .iter()
            .position(|o| o.name == name)
            .map(|i| ObjectId(i as u32))
    }

    /// The id of the object with this name, or `SimError::UnknownObject`.
    pub fn lookup(&self, name: &str) -> Result<ObjectId, SimError> {
        self.find(name)
            .ok_or_else(|| SimError::UnknownObject(name.to_string()))
    }

    /// The object with this id.
    pub fn object(&self, id: ObjectId) -> &SceneObject {
        &self.objects[id.index()]
    }

    /// The id of the held object, if any.
    pub fn held(&self) -> Option<ObjectId> {
        self.in_hand.as_deref().and_then(|n| self.find(n))
    }

    /// All object ids.
    pub fn ids(&self) -> impl Iterator<Item = ObjectId> {
        (0..self.objects.len() as u32).map(ObjectId)
    }

    /// Parses and validates a scene from JSON.
    pub fn from_json(text: &str) -> Result<Scene, SimError> {
        let mut scene: Scene =
            serde_json::from_str(text).map_err(|e| SimError::MalformedScene(e.to_string()))?;
        scene.validate()?;
        for object in &mut scene.objects {
            let q = Rot3::from_array(object.rotation).normalize();
            object.rotation = q.to_array();
        }
        Ok(scene)
    }

    /// Serialises the scene as pretty JSON.
    pub fn to_json(&self) -> String {
        serde_json::to_string_pretty(self).expect("a scene always serialises")
    }

    /// Checks the invariants listed in the module documentation.
    pub fn validate(&self) -> Result<(), SimError> {
        let bad = |msg: String| Err(SimError::MalformedScene(msg));
        if !is_constant(&self.robot) {
            return bad(format!(
                "robot name `{}` is not a lower-case constant",
                self.robot
            ));
        }
        for (i, object) in self.objects.iter().enumerate() {
            if !is_constant(&object.name) {
                return bad(format!(
                    "object name `{}` is not a lower-case constant",
                    object.name
                ));
            }
            if object.name == TABLE || object.name == self.robot {
                return bad(format!("object name `{}` is reserved", object.name));
            }
            if self.objects[..i].iter().any(|o| o.name == object.name) {
                return bad(format!("object name `{}` appears twice", object.name));
            }
            if !object
                .position
                .iter()
                .chain(&object.rotation)
                .all(|v| v.is_finite())
            {
                return bad(format!("object `{}` has a non-finite pose", object.name));
            }
            let norm: f32 = object.rotation.iter().map(|v| v * v).sum();
            if norm < 1e-6 {
                return bad(format!(
                    "object `{}` has a zero rotation quaternion",
                    object.name
                ));
            }
        }
        if let Some(held) = &self.in_hand {
            if self.find(held).is_none() {
                return bad(format!(
                    "in_hand names `{held}`, which is not an object of the scene"
                ));
            }
        }
        let c = &self.camera;
        if !c.eye.iter().chain(&c.target).all(|v| v.is_finite())
            || c.eye == c.target
            || !(1.0..=170.0).contains(&c.fov_y_degrees)
        {
            return bad("the camera needs finite, distinct eye and target and a sane fov".into());
        }
        Ok(())
    }
}

/// True for a clingo-style constant: a lower-case letter, then letters, digits or underscores.
pub fn is_constant(name: &str) -> bool {
    let mut chars = name.chars();
    matches!(chars.next(), Some(c) if c.is_ascii_lowercase())
        && chars.all(|c| c.is_ascii_alphanumeric() || c == '_')
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn json_round_trip() {
        let mut scene = Scene::custom(3);
        scene.add_resting(
            "red_cube",
            ObjectKind::Cube,
            Colour::Red,
            Size::Large,
            (0.0, 0.0, 0.0),
        );
        let back = Scene::from_json(&scene.to_json()).unwrap();
        assert_eq!(back, scene);
    }

    #[test]
    fn malformed_scenes_are_errors() {
        assert!(matches!(
            Scene::from_json("{"),
            Err(SimError::MalformedScene(_))
        ));
        let mut scene = Scene::custom(3);
        scene.add_resting(
            "a",
            ObjectKind::Cube,
            Colour::Red,
            Size::Large,
            (0.0, 0.0, 0.0),
        );
        scene.in_hand = Some("b".into());
        assert!(matches!(
            Scene::from_json(&scene.to_json()),
            Err(SimError::MalformedScene(_))
        ));
        let text = scene.to_json().replace("\"a\"", "\"Table\"");
        assert!(matches!(
            Scene::from_json(&text),
            Err(SimError::MalformedScene(_))
        ));
    }
}
