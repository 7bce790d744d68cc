//! Layouts of games tables that a plain table cannot show: a foosball table (a walled cabinet
//! on legs with a green pitch, goals at both ends and rods across it carrying rows of players,
//! each rod sticking out past both long sides with a handle on one) and a roulette table (a
//! wooden rail round green felt, the betting layout of red and black cells at one end and the
//! wheel in its bowl at the other). Long axis along x; the players' sides are ±y.
use super::archetypes::Builder;
use super::materials::Role::*;

/// A foosball table. The cabinet is narrower than the size box's depth so the rods' ends and
/// handles fit inside it.
pub fn foosball(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let cd = 0.62 * hd;
    let (zp, zt) = (0.72 * h, h);
    let t = 0.03 * hd.max(0.5);
    // Four legs and a cross rail, the pitch, the walls round it.
    for sx in [-1.0, 1.0] {
        for sy in [-1.0, 1.0] {
            let (x, y) = (sx * (hw - 0.1 * hw), sy * (cd - 0.1 * cd));
            b.cuboid(Frame, [x - 0.04, y - 0.04, 0.0], [x + 0.04, y + 0.04, zp]);
        }
    }
    b.cuboid(
        Frame,
        [-0.85 * hw, -0.03, 0.15 * h],
        [0.85 * hw, 0.03, 0.2 * h],
    );
    b.cuboid(Body, [-hw, -cd, zp - 0.1 * h], [hw, cd, zp]);
    b.cuboid(Canvas, [-hw + t, -cd + t, zp], [hw - t, cd - t, zp + 0.005]);
    for sy in [-1.0, 1.0] {
        let (y0, y1) = if sy < 0.0 {
            (-cd, -cd + t)
        } else {
            (cd - t, cd)
        };
        b.cuboid(Body, [-hw, y0, zp - 0.1 * h], [hw, y1, zt - 0.02 * h]);
    }
    for sx in [-1.0, 1.0] {
        let (x0, x1) = if sx < 0.0 {
            (-hw, -hw + t)
        } else {
            (hw - t, hw)
        };
        b.cuboid(Body, [x0, -cd, zp - 0.1 * h], [x1, cd, zt - 0.02 * h]);
        // The goal mouth.
        b.cuboid(
            Interior,
            [sx * (hw - t) - 0.002, -0.25 * cd, zp],
            [sx * (hw - t) + 0.002, 0.25 * cd, zp + 0.08 * h],
        );
    }
    // Pitch markings: a halfway line and centre spot.
    b.cuboid(
        Cushion,
        [-0.004, -cd + t, zp + 0.005],
        [0.004, cd - t, zp + 0.007],
    );
    // Eight rods, alternately of the two teams, their handles on the team's own side.
    let zr = zp + 0.6 * (zt - 0.02 * h - zp);
    let rr = 0.008;
    let players = [1, 2, 3, 5, 5, 3, 2, 1];
    for (i, &n) in players.iter().enumerate() {
        let x = -hw + 2.0 * hw * (i as f64 + 0.5) / players.len() as f64;
        let team = i % 2 == 0;
        let (role, side) = if team {
            (Upholstery, 1.0)
        } else {
            (Seat, -1.0)
        };
        let reach = hd - 0.14 * hd;
        b.rod(Metal, [x, -reach, zr], [x, reach, zr], rr);
        b.rod(Handle, [x, side * reach, zr], [x, side * hd, zr], 2.5 * rr);
        for k in 0..n {
            let y = -cd + t + (2.0 * (cd - t)) * (k as f64 + 0.5) / n as f64;
            b.cuboid(
                role,
                [x - 0.012, y - 0.02, zp + 0.02],
                [x + 0.012, y + 0.02, zr + 0.03],
            );
            b.ellipsoid(Skin, [x, y, zr + 0.045], [0.015, 0.015, 0.017]);
        }
    }
}

/// A roulette table: legs under a wooden rail round green felt; the layout (three rows of
/// twelve red and black numbers with the green zero) over the +x two thirds, the wheel (a
/// wooden bowl, the pocketed rotor and a brass spindle) at the −x end.
pub fn roulette(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let zt = 0.82 * h;
    for sx in [-1.0, 1.0] {
        for sy in [-1.0, 1.0] {
            let (x, y) = (sx * 0.85 * hw, sy * 0.75 * hd);
            b.cuboid(Frame, [x - 0.05, y - 0.05, 0.0], [x + 0.05, y + 0.05, zt]);
        }
    }
    b.cuboid(Frame, [-hw, -hd, zt - 0.08 * h], [hw, hd, zt]);
    let rail = 0.08 * hd.max(0.5);
    b.cuboid(
        Canvas,
        [-hw + rail, -hd + rail, zt],
        [hw - rail, hd - rail, zt + 0.004],
    );
    for sy in [-1.0, 1.0] {
        let y = sy * (hd - rail / 2.0);
        b.rod(
            Frame,
            [-hw + rail / 2.0, y, zt + 0.02],
            [hw - rail / 2.0, y, zt + 0.02],
            rail / 2.0,
        );
    }
    for sx in [-1.0, 1.0] {
        let x = sx * (hw - rail / 2.0);
        b.rod(
            Frame,
            [x, -hd + rail / 2.0, zt + 0.02],
            [x, hd - rail / 2.0, zt + 0.02],
            rail / 2.0,
        );
    }
    // The layout: the zero, then 3 x 12 cells, alternating red and black, lined in white.
    let (x0, x1) = (-0.1 * hw, hw - 2.0 * rail);
    let (y0, y1) = (-0.55 * hd, 0.6 * hd);
    let z = zt + 0.005;
    b.cuboid(
        Cushion,
        [x0 - 0.005, y0 - 0.005, z - 0.0005],
        [x1 + 0.005, y1 + 0.005, z],
    );
    let zero = 0.08 * (x1 - x0);
    b.cuboid(Foliage, [x0, y0, z], [x0 + zero - 0.004, y1, z + 0.001]);
    let (cw, ch) = ((x1 - x0 - zero) / 12.0, (y1 - y0) / 3.0);
    for i in 0..12 {
        for j in 0..3 {
            let red = (i + j) % 2 == 0;
            let xa = x0 + zero + i as f64 * cw;
            let ya = y0 + j as f64 * ch;
            b.cuboid(
                if red { Upholstery } else { BlackKeys },
                [xa + 0.004, ya + 0.004, z],
                [xa + cw - 0.004, ya + ch - 0.004, z + 0.001],
            );
        }
    }
    // The wheel: a bowl, a rotor of pockets, a cone and its spindle.
    let rw = (0.75 * hd).min(0.4 * hw);
    let xw = -hw + rail + rw + 0.04 * hw;
    let zb = zt;
    b.revolved(
        Frame,
        0,
        [xw, 0.0, zb],
        super::parts::IDENTITY,
        1.0,
        vec![
            [rw, 0.0],
            [rw, 0.12 * h],
            [0.92 * rw, 0.12 * h],
            [0.85 * rw, 0.08 * h],
        ],
    );
    let zr = zb + 0.08 * h;
    let n = 18;
    for k in 0..n {
        let a0 = std::f64::consts::TAU * k as f64 / n as f64;
        let role = if k == 0 {
            Foliage
        } else if k % 2 == 0 {
            Upholstery
        } else {
            BlackKeys
        };
        let c = [xw + 0.62 * rw * a0.cos(), 0.62 * rw * a0.sin(), zr];
        b.slab(
            role,
            c,
            [0.2 * rw, 0.1 * rw, 0.004],
            super::parts::rot_z(a0),
        );
    }
    b.frustum(Top, [xw, 0.0, zr], 0.4 * rw, 0.4 * rw, 0.3, 0.04 * h);
    b.rod(Metal, [xw, 0.0, zr], [xw, 0.0, zr + 0.1 * h], 0.03 * rw);
    for a in [0.0, std::f64::consts::FRAC_PI_2] {
        let (c, s) = (a.cos(), a.sin());
        b.rod(
            Metal,
            [xw - 0.15 * rw * c, -0.15 * rw * s, zr + 0.08 * h],
            [xw + 0.15 * rw * c, 0.15 * rw * s, zr + 0.08 * h],
            0.015 * rw,
        );
    }
}
