use super::*;

#[test]
fn footprints_cut_the_floor_and_rugs_do_not() {
    let agent = Agent::default();
    let bed = Obstacle {
        centre: [0.0, 0.0],
        half: [0.8, 1.0],
        yaw: 30.0,
        z: [0.0, 1.0],
    };
    let rug = Obstacle {
        centre: [1.5, 1.0],
        half: [1.0, 0.7],
        yaw: 0.0,
        z: [0.0, 0.005],
    };
    let m = NavMesh::build([5.0, 4.0], &[bed, rug], agent, 0.1);
    // No walkable cell centre (nor any of its corners) lies in the inflated bed.
    for k in 0..m.walkable.len() {
        if m.walkable[k] {
            let c = m.centre(k);
            for dx in [-0.05, 0.05] {
                for dy in [-0.05, 0.05] {
                    assert!(!bed.contains([c[0] + dx, c[1] + dy], agent.radius - 1e-9));
                }
            }
        }
    }
    // The rug's middle stays walkable; the floor far from the bed too.
    let on_rug = m.cell_of([1.55, 1.05]).expect("in room");
    assert!(m.walkable[on_rug.1 * m.nx + on_rug.0]);
    let area = m.area();
    let cut = (1.6 + 0.5) * (2.0 + 0.5);
    let free = (5.0 - 0.5) * (4.0 - 0.5);
    assert!(area < free - cut * 0.9 && area > free - cut * 1.6, "{area}");
    // Every triangle is a walkable cell's half and vertices are shared.
    assert_eq!(
        m.triangles.len(),
        2 * m.walkable.iter().filter(|w| **w).count()
    );
    assert!(m.vertices.len() < 2 * m.triangles.len());
    let spawns = m.spawn_points(&[], 2);
    assert_eq!(spawns.len(), 2);
    for (p, _) in spawns {
        assert!(!bed.contains([p[0], p[1]], agent.radius));
    }
}

#[test]
fn spawns_skip_a_pocket_beside_the_door() {
    let agent = Agent::default();
    // A counter along the south wall, a stove east of it and an island north of both leave a
    // pocket; the door's inside point lies in the pocket, the open room beyond the island.
    let counter = Obstacle {
        centre: [0.0, -1.6],
        half: [1.0, 0.35],
        yaw: 0.0,
        z: [0.0, 0.9],
    };
    let stove = Obstacle {
        centre: [2.2, -1.5],
        half: [0.25, 0.5],
        yaw: 0.0,
        z: [0.0, 0.9],
    };
    let island = Obstacle {
        centre: [1.5, -0.6],
        half: [0.85, 0.2],
        yaw: 0.0,
        z: [0.0, 0.9],
    };
    let m = NavMesh::build([5.0, 4.0], &[counter, stove, island], agent, 0.1);
    let door = [1.45, -1.5];
    let pocket = m.cell_of(door).expect("in room");
    let k = pocket.1 * m.nx + pocket.0;
    assert!(m.walkable[k], "the pocket is walkable");
    let main = m.largest_region();
    assert!(!main[k], "the pocket is not the main region");
    let spawns = m.spawn_points(&[door], 2);
    assert_eq!(spawns.len(), 2, "two spawns");
    for (p, _) in &spawns {
        let c = m.cell_of([p[0], p[1]]).expect("in room");
        assert!(main[c.1 * m.nx + c.0], "spawn {p:?} on the main region");
    }
    // The door spawn is still the main region's nearest cell to the door.
    let d0 = ((spawns[0].0[0] - door[0]).powi(2) + (spawns[0].0[1] - door[1]).powi(2)).sqrt();
    assert!(
        d0 < 1.5,
        "door spawn {:?} is {d0} m from the door",
        spawns[0]
    );
}

/// Surface samples of a 2 x 2 x 2.5 m patio umbrella in its own frame: a 0.3 m base plate (6 cm,
/// under the agent's step), a 2 cm pole standing at `pole` and a canopy from 1.9 m up.
fn umbrella(pole: [f64; 2]) -> Vec<([f64; 3], f64)> {
    let mut s = vec![];
    for k in 0..24 {
        let a = f64::from(k) / 24.0 * std::f64::consts::TAU;
        for r in [0.05, 0.15] {
            s.push(([pole[0] + r * a.cos(), pole[1] + r * a.sin(), 0.06], 0.02));
        }
        for (r, z) in [(1.0, 1.9), (0.6, 2.1), (0.2, 2.35)] {
            s.push(([r * a.cos(), r * a.sin(), z], 0.05));
        }
    }
    for k in 0..24 {
        s.push(([pole[0], pole[1], 0.06 + f64::from(k) * 0.1], 0.015));
    }
    s
}

#[test]
fn a_canopy_above_the_head_is_walked_under() {
    let agent = Agent::default();
    let whole = Obstacle {
        centre: [1.0, -0.5],
        half: [1.0, 1.0],
        yaw: 90.0,
        z: [0.0, 2.5],
    };
    // The pole stands 0.4 m along the umbrella's own x, which the yaw turns to the world's +y.
    let pole = whole
        .walked_into(&agent, &umbrella([0.4, 0.0]))
        .expect("the pole blocks");
    assert!(
        (pole.centre[0] - 1.0).abs() < 1e-9 && (pole.centre[1] + 0.1).abs() < 1e-9,
        "{pole:?}"
    );
    assert!(
        pole.half.iter().all(|h| (h - 0.015).abs() < 1e-9),
        "only the pole: {pole:?}"
    );
    // Beside the pole, under the canopy, the floor is walkable; it was not with the whole box.
    let under = [1.0 + 0.6, -0.1];
    for (obstacle, walkable) in [(pole, true), (whole, false)] {
        let m = NavMesh::build([6.0, 5.0], &[obstacle], agent, 0.05);
        let (i, j) = m.cell_of(under).expect("in room");
        assert_eq!(m.walkable[j * m.nx + i], walkable, "{obstacle:?}");
        let (i, j) = m.cell_of(pole.centre).expect("in room");
        assert!(!m.walkable[j * m.nx + i], "the pole's own cell");
    }
    // Something no taller than the agent blocks with its whole footprint, whatever its samples;
    // with no samples a tall one does too; with all of them above the head, nothing blocks.
    let table = Obstacle {
        z: [0.0, 0.75],
        ..whole
    };
    assert_eq!(table.walked_into(&agent, &umbrella([0.0; 2])), Some(table));
    assert_eq!(whole.walked_into(&agent, &[]), Some(whole));
    let high: Vec<([f64; 3], f64)> = umbrella([0.0; 2])
        .into_iter()
        .filter(|(p, _)| p[2] > 1.85)
        .collect();
    assert_eq!(whole.walked_into(&agent, &high), None);
    // A rug-like object under the agent's step blocks nothing at all.
    let rug = Obstacle {
        z: [0.0, 0.01],
        ..whole
    };
    assert_eq!(rug.walked_into(&agent, &[]), None);
}
