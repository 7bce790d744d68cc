//! The archetype table: each archetype's name, the roles its first colour word paints, its
//! default colours, and the function that lays out its parts (with the [`Builder`] of
//! `builder.rs`, re-exported here for the layout modules).
use super::amusements as am;
use super::appliances as a;
use super::audio as au;
use super::backyard as by;
use super::barriers as ba;
use super::beasts as bs;
use super::bellhop as bh;
use super::bins as bn;
use super::boards as bd;
use super::boathouse as bt;
use super::booths as bo;
use super::bowls as bw;
use super::braziers as bz;
pub use super::builder::{frame_along, Builder};
use super::canopy as cb;
use super::care as cw;
use super::carts as ca;
use super::cases as c;
use super::clearglass as cg;
use super::clocks as ck;
use super::coast as co;
use super::contraptions as cn;
use super::counters as scn;
use super::crafts as cr;
use super::crates as cx;
use super::daily as d;
use super::displays as dp;
use super::drapes as dra;
use super::drawers as dr;
use super::effigies as ef;
use super::engines as en;
use super::everyday as ev;
use super::fixtures as fx;
use super::florist as fl;
use super::forms as fo;
use super::fossils as fos;
use super::fowl as fw;
use super::frames as fr;
use super::furniture as f;
use super::gadgets as gd;
use super::games as gm;
use super::garden as ga;
use super::gizmos as gi;
use super::glasshouse as gh;
use super::glazed as gz;
use super::grounds as gr;
use super::gym;
use super::hangings as hg;
use super::heritage as he;
use super::holders as hr;
use super::homefit as hf;
use super::household as ho;
use super::instruments as ins;
use super::jobtables as jt;
use super::kiosks as ks;
use super::kitchenyard as ky;
use super::lair as lr;
use super::laundry as la;
use super::lockers as lk;
use super::lounge as lo;
use super::machines as ma;
use super::markers as mr;
use super::market as mk;
use super::materials::{Rgb, Role};
use super::mirrors as mi;
use super::more as m;
use super::named as nm;
use super::nursery as nu;
use super::officefit as of;
use super::orchard as oc;
use super::ornaments as or;
use super::ovens as ov;
use super::packs as pk;
use super::parlour as pa;
use super::partitions as pn;
use super::parts::Part;
use super::pegs as pg;
use super::pets as pe;
use super::picnic as pc;
use super::plants as pt;
use super::play as pl;
use super::podiums as pd;
use super::poles as po;
use super::ponds as pond;
use super::prints as pr;
use super::racks as rk;
use super::recliners as rc;
use super::redrawn as rw;
use super::riders as rd;
use super::rigs;
use super::rocks;
use super::salon as sa;
use super::scopes as sco;
use super::sculpted as sc;
use super::seats as se;
use super::servers as sv;
use super::sets as sx;
use super::sewing as sw;
use super::skeleton as sk;
use super::sleepers as sl;
use super::smithy as sm;
use super::sport as sp;
use super::stands as sd;
use super::streetside as ss;
use super::structures as st;
use super::sundries as su;
use super::surgical as sg;
use super::tanks as tk;
use super::taps as tp;
use super::textiles as tx;
use super::things as t;
use super::training as tr;
use super::transit as tt;
use super::utility as ut;
use super::vanities as va;
use super::vehicles as ve;
use super::vendors as vd;
use super::vitrines as vi;
use super::wards as wd;
use super::washroom as wa;
use super::workshop as ws;
use super::worktops as wt;
use super::yard as yd;

/// One archetype.
pub struct Archetype {
    pub name: &'static str,
    /// Roles the first colour word of a description paints.
    pub main: &'static [Role],
    /// Colours that replace the role defaults for this archetype.
    pub defaults: &'static [(Role, Rgb)],
    pub layout: fn(&mut Builder),
}

impl Archetype {
    /// The parts at `size`, shelves holding `goods`, a quadruped drawn as `animal`, a bird as
    /// `bird`, held up as `mount` says.
    pub fn parts_holding(
        &self,
        size: [f64; 3],
        goods: Option<super::goods::Goods>,
        animal: Option<&'static super::animals::Animal>,
        bird: Option<&'static super::birds::Bird>,
        variant: u32,
        mount: super::Mount,
    ) -> Vec<Part> {
        let mut b = Builder {
            parts: vec![],
            w: size[0],
            d: size[1],
            h: size[2],
            goods,
            animal,
            bird,
            variant: variant % super::variants::count(self.name),
            mount: mount.drawn(),
        };
        (self.layout)(&mut b);
        b.parts
    }
}

use Role::*;

const WHITE: Rgb = [0.92, 0.92, 0.91];
const STEEL: Rgb = [0.72, 0.73, 0.75];
const BLACK: Rgb = [0.08, 0.08, 0.09];
const DARK_WOOD: Rgb = [0.30, 0.19, 0.11];
const BRASS: Rgb = [0.72, 0.56, 0.28];
const STONE: Rgb = [0.66, 0.64, 0.60];
/// Silvered glass: pale, a little blue, brighter than a white wall's shade so it reads as glass.
const MIRROR_GLASS: Rgb = [0.82, 0.89, 0.94];

macro_rules! arch {
    ($name:literal, $layout:expr, [$($main:expr),*], [$($role:expr => $rgb:expr),*]) => {
        Archetype { name: $name, main: &[$($main),*], defaults: &[$(($role, $rgb)),*], layout: $layout }
    };
}

/// Every archetype.
pub const ARCHETYPES: &[Archetype] = &[
    arch!("box", m::solid_box, [Body, Top], []),
    arch!("cardboard_boxes", cx::cardboard_boxes, [Body], [Body => [0.70, 0.54, 0.36], Handle => [0.78, 0.66, 0.48]]),
    arch!("ballot_box", cx::ballot_box, [Frame, Top], [Frame => [0.12, 0.13, 0.16], Top => [0.14, 0.20, 0.42], Pane => [0.78, 0.86, 0.90], Books => [0.95, 0.94, 0.90], Handle => [0.80, 0.12, 0.10], Canvas => [0.93, 0.93, 0.95], Interior => [0.03, 0.03, 0.04]]),
    arch!("crate", cx::crate_box, [Body, Top, Frame], [Body => [0.68, 0.52, 0.34], Top => [0.68, 0.52, 0.34], Frame => [0.60, 0.45, 0.28], Interior => [0.25, 0.18, 0.11]]),
    arch!("cargo_container", cx::cargo_container, [Body, Door], [Body => [0.72, 0.22, 0.14], Door => [0.72, 0.22, 0.14], Frame => [0.62, 0.19, 0.12], Metal => [0.30, 0.30, 0.32], Handle => [0.55, 0.56, 0.58]]),
    arch!("hay_bale", cx::hay_bale, [Body], [Body => [0.86, 0.74, 0.42], Handle => [0.55, 0.42, 0.25]]),
    arch!("backpack", pk::backpack, [Body, Top], [Body => [0.18, 0.33, 0.52], Top => [0.16, 0.17, 0.19], Cushion => [0.16, 0.17, 0.19], Handle => BLACK]),
    arch!("bathroom_scale", pk::bathroom_scale, [Body], [Body => WHITE, Glass => [0.80, 0.84, 0.86], Screen => [0.12, 0.12, 0.13], Canvas => WHITE, Handle => [0.85, 0.12, 0.10]]),
    arch!("bread_bin", pk::bread_bin, [Body, Top], [Body => [0.90, 0.88, 0.80], Top => [0.90, 0.88, 0.80], Handle => [0.55, 0.38, 0.22]]),
    arch!("litter_box", pk::litter_box, [Top, Body], [Body => [0.50, 0.52, 0.56], Top => [0.86, 0.86, 0.84], Interior => BLACK, Handle => [0.50, 0.52, 0.56]]),
    arch!("magazines", pk::magazines, [Books], [Canvas => WHITE]),
    arch!("shopping_basket", pk::shopping_basket, [Frame, Top, Body], [Frame => [0.80, 0.12, 0.12], Body => [0.80, 0.12, 0.12], Top => [0.80, 0.12, 0.12], Handle => BLACK]),
    arch!("fitting_room", bo::fitting_room, [Upholstery], [Body => [0.88, 0.86, 0.82], Frame => [0.88, 0.86, 0.82], Upholstery => [0.48, 0.12, 0.16], Seat => [0.55, 0.38, 0.22], Interior => [0.55, 0.55, 0.56], Handle => STEEL, Metal => STEEL]),
    arch!("photo_booth", bo::photo_booth, [Body], [Body => [0.72, 0.12, 0.12], Top => BLACK, Upholstery => [0.12, 0.12, 0.14], Light => [0.98, 0.96, 0.90], Seat => STEEL, Interior => BLACK, Handle => STEEL, Metal => STEEL]),
    arch!("curtains", dra::curtains, [Upholstery], [Upholstery => [0.78, 0.72, 0.62], Cushion => [0.62, 0.52, 0.40], Metal => BRASS]),
    arch!("privacy_curtain", dra::privacy_curtain, [Upholstery], [Upholstery => [0.62, 0.78, 0.80], Canvas => [0.92, 0.92, 0.91], Metal => STEEL]),
    arch!("security_gate", bo::security_gate, [Body], [Body => [0.62, 0.64, 0.67], Top => [0.30, 0.30, 0.32], Frame => BLACK, Light => [0.35, 0.90, 0.40]]),
    arch!("turnstile", bo::turnstile, [Body], [Body => STEEL, Top => BLACK, Metal => [0.82, 0.83, 0.85], Light => [0.35, 0.90, 0.40]]),
    arch!("photo_backdrop", bo::photo_backdrop, [Canvas], [Metal => BLACK]),
    arch!("dock", gr::dock, [Top], [Top => [0.58, 0.47, 0.34], Trunk => [0.33, 0.25, 0.17], Frame => [0.40, 0.30, 0.20]]),
    arch!("firewood_pile", gr::firewood_pile, [Trunk], [Trunk => [0.36, 0.26, 0.17], Top => [0.82, 0.68, 0.48]]),
    arch!("compost_bin", gr::compost_bin, [Body, Frame], [Body => [0.52, 0.38, 0.23], Frame => [0.42, 0.30, 0.18], Soil => [0.20, 0.14, 0.09]]),
    arch!("sandbox", gr::sandbox, [Frame, Top], [Frame => [0.62, 0.46, 0.28], Top => [0.70, 0.54, 0.34], Soil => [0.88, 0.80, 0.60], Seat => [0.85, 0.20, 0.15]]),
    arch!("obelisk", gr::obelisk, [Stone, Top, Frame], [Stone => STONE, Top => STONE, Frame => [0.58, 0.56, 0.52]]),
    arch!("dog_crate", gr::dog_crate, [Metal], [Metal => [0.14, 0.14, 0.15], Body => [0.22, 0.22, 0.24], Handle => STEEL]),
    arch!("forge", sm::forge, [Body], [Body => [0.56, 0.26, 0.18], Top => [0.32, 0.30, 0.28], Metal => [0.16, 0.16, 0.17], Interior => BLACK, Light => [1.0, 0.55, 0.15], Trunk => [0.45, 0.32, 0.20]]),
    arch!("furnace", sm::furnace, [Body], [Body => [0.20, 0.20, 0.21], Frame => [0.35, 0.33, 0.30], Top => [0.26, 0.26, 0.27], Door => [0.14, 0.14, 0.15], Light => [1.0, 0.50, 0.12], Interior => BLACK, Handle => STEEL, Metal => [0.30, 0.30, 0.32]]),
    arch!("camp_stove", sm::camp_stove, [Body], [Body => [0.20, 0.42, 0.25], Interior => BLACK, Metal => STEEL, Light => [0.35, 0.55, 1.0], Handle => BLACK]),
    arch!("vise", sm::vise, [Body], [Body => [0.20, 0.35, 0.60], Metal => STEEL, Handle => STEEL]),
    arch!("stage_monitor", sm::stage_monitor, [Body], [Body => BLACK, Screen => [0.18, 0.18, 0.19], Interior => BLACK]),
    arch!("train_set", sm::train_set, [Top], [Top => [0.80, 0.64, 0.44], Metal => [0.58, 0.44, 0.30], Body => [0.80, 0.15, 0.12], Door => [0.20, 0.40, 0.75], Interior => BLACK, Tyre => BLACK]),
    arch!("operating_table", wd::operating_table, [Upholstery], [Upholstery => [0.16, 0.19, 0.22], Frame => STEEL, Metal => [0.82, 0.83, 0.85]]),
    arch!("theater_seat", wd::theater_seat, [Upholstery], [Upholstery => [0.60, 0.08, 0.10], Body => BLACK, Frame => [0.15, 0.15, 0.16], Top => DARK_WOOD, Metal => BLACK]),
    arch!("nursing_chair", wd::nursing_chair, [Upholstery, Cushion], [Upholstery => [0.74, 0.70, 0.64], Cushion => [0.78, 0.74, 0.68], Frame => [0.60, 0.45, 0.30]]),
    arch!("card_catalog", dr::card_catalog, [Body, Door, Top, Frame], [Body => [0.62, 0.44, 0.26], Door => [0.66, 0.48, 0.29], Top => [0.58, 0.41, 0.24], Frame => [0.58, 0.41, 0.24], Handle => BRASS]),
    arch!("tool_chest", dr::tool_chest, [Body, Door], [Body => [0.76, 0.08, 0.08], Door => [0.76, 0.08, 0.08], Top => BLACK, Handle => STEEL, Metal => STEEL, Tyre => BLACK]),
    arch!("medical_cart", dr::medical_cart, [Body], [Body => [0.88, 0.89, 0.90], Door => [0.50, 0.68, 0.84], Top => [0.55, 0.56, 0.58], Metal => STEEL, Handle => STEEL, Tyre => BLACK]),
    arch!("changing_table", dr::changing_table, [Body, Door, Top, Frame], [Body => WHITE, Door => WHITE, Top => WHITE, Frame => WHITE, Cushion => [0.74, 0.85, 0.90], Handle => STEEL]),
    arch!("table", f::table, [Top, Frame], []),
    arch!("round_table", f::round_table, [Top, Frame], []),
    arch!("desk", f::desk, [Top, Body, Door, Frame], []),
    arch!("chair", f::chair, [Seat], []),
    arch!("armchair", f::armchair, [Upholstery, Cushion], [Frame => DARK_WOOD]),
    arch!("sofa", f::sofa, [Upholstery, Cushion], [Frame => DARK_WOOD]),
    arch!("office_chair", f::office_chair, [Upholstery], [Upholstery => [0.14, 0.14, 0.15], Metal => [0.18, 0.18, 0.19]]),
    arch!("stool", f::stool, [Seat], [Frame => [0.25, 0.25, 0.27]]),
    arch!("bench", f::bench, [Seat, Frame], []),
    arch!("ottoman", f::ottoman, [Upholstery], [Upholstery => [0.55, 0.45, 0.38]]),
    arch!("bed", f::bed, [Duvet], [Duvet => [0.62, 0.68, 0.76]]),
    arch!("bunk_bed", f::bunk_bed, [Frame], [Duvet => [0.35, 0.48, 0.66]]),
    arch!("cabinet", c::cabinet, [Body, Door, Top], []),
    arch!("dresser", c::dresser, [Body, Door, Top], []),
    arch!("wardrobe", c::wardrobe, [Body, Door, Top], []),
    arch!("sideboard", c::sideboard, [Body, Door, Top], []),
    arch!("shelf", c::shelf, [Frame], [Interior => DARK_WOOD]),
    arch!("rack", c::rack, [Frame], [Frame => [0.40, 0.41, 0.43]]),
    arch!("floor_lamp", c::floor_lamp, [Shade], []),
    arch!("table_lamp", c::table_lamp, [Body], [Body => [0.85, 0.82, 0.76]]),
    arch!("task_lamp", c::task_lamp, [Shade, Metal], [Shade => [0.10, 0.10, 0.11], Metal => [0.12, 0.12, 0.13], Light => [1.0, 0.96, 0.85]]),
    arch!("rug", c::rug, [Upholstery], [Upholstery => [0.62, 0.28, 0.22], Cushion => [0.86, 0.79, 0.63]]),
    arch!("counter", c::counter, [Body, Door], [Top => [0.82, 0.80, 0.76]]),
    arch!("service_counter", scn::service_counter, [Body, Door], [Top => [0.82, 0.80, 0.76], Door => [0.66, 0.50, 0.33], Interior => [0.22, 0.17, 0.13]]),
    arch!("bar_counter", scn::bar_counter, [Body, Door], [Top => DARK_WOOD, Body => [0.45, 0.30, 0.18], Door => [0.50, 0.34, 0.20], Interior => [0.18, 0.13, 0.09], Metal => BRASS]),
    arch!("sink", c::sink, [Body, Door], [Top => [0.82, 0.80, 0.76], Canvas => WHITE, Metal => STEEL]),
    arch!("fireplace", c::fireplace, [Body], [Body => STONE, Top => DARK_WOOD]),
    arch!("piano", c::piano, [Body], [Body => BLACK, Frame => BLACK]),
    arch!("grand_piano", c::grand_piano, [Body, Top], [Body => BLACK, Top => BLACK, Frame => BLACK, Metal => [0.78, 0.62, 0.30]]),
    arch!("bathtub", c::bathtub, [Body], [Body => WHITE, Canvas => [0.86, 0.88, 0.90]]),
    arch!("toilet", c::toilet, [Body], [Body => WHITE, Top => WHITE]),
    arch!("plant", m::plant, [Foliage], []),
    arch!("tree", m::tree, [Foliage], []),
    arch!("bush", m::bush, [Foliage], []),
    arch!("conifer", m::conifer, [Foliage], [Foliage => [0.10, 0.36, 0.16]]),
    arch!("screen", m::screen, [Body], [Body => BLACK, Metal => [0.15, 0.15, 0.16]]),
    arch!("board", m::board, [Canvas], [Frame => [0.70, 0.71, 0.73]]),
    arch!("chalkboard", m::chalkboard, [Canvas], [Canvas => [0.15, 0.25, 0.20]]),
    arch!("painting", m::painting, [Frame], [Frame => [0.62, 0.48, 0.22]]),
    arch!("mirror", m::mirror, [Frame], [Canvas => MIRROR_GLASS]),
    arch!("wall_map", pr::wall_map, [Water], [Frame => [0.30, 0.20, 0.12], Water => [0.40, 0.62, 0.82], Foliage => [0.30, 0.62, 0.22], Soil => [0.90, 0.72, 0.35], Canvas => [0.85, 0.88, 0.92]]),
    arch!("calendar", pr::calendar, [Canvas], [Canvas => WHITE, Body => [0.55, 0.75, 0.92], Foliage => [0.35, 0.62, 0.30], Top => [0.80, 0.14, 0.12], Frame => [0.72, 0.72, 0.75], Handle => [0.90, 0.55, 0.55], Metal => [0.55, 0.55, 0.57]]),
    arch!("poster", hg::poster, [Body], [Canvas => [0.95, 0.94, 0.90], Body => [0.16, 0.30, 0.52], Cushion => [0.92, 0.62, 0.18], Frame => [0.12, 0.12, 0.14], Metal => [0.75, 0.75, 0.75]]),
    arch!("mirror_wall", mi::mirror_wall, [Metal], [Canvas => MIRROR_GLASS, Metal => [0.74, 0.75, 0.77]]),
    arch!("fridge", a::fridge, [Body, Door], [Body => STEEL, Door => STEEL, Handle => [0.22, 0.22, 0.24]]),
    arch!("washer", a::washer, [Body, Door], [Body => WHITE, Door => WHITE, Metal => STEEL, Frame => [0.55, 0.55, 0.56], Handle => [0.25, 0.40, 0.75]]),
    arch!("wall_oven", la::wall_oven, [Body, Door], [Body => STEEL, Door => STEEL, Screen => BLACK, Metal => STEEL, Handle => [0.80, 0.80, 0.82], Light => [0.35, 0.85, 0.95], Frame => [0.45, 0.45, 0.46]]),
    arch!("stove", a::stove, [Body, Door], [Body => STEEL, Door => STEEL, Top => BLACK]),
    arch!("arcade", ks::arcade, [Canvas], [Body => [0.09, 0.09, 0.11], Screen => [0.22, 0.45, 0.72], Canvas => [0.20, 0.35, 0.90], Top => [0.14, 0.14, 0.17], Door => [0.30, 0.30, 0.33], Light => [1.0, 0.85, 0.35], Handle => [0.90, 0.12, 0.10], Metal => STEEL, Frame => [0.16, 0.16, 0.18], Interior => BLACK]),
    arch!("atm", ks::atm, [Canvas], [Body => [0.70, 0.71, 0.73], Canvas => [0.10, 0.32, 0.65], Top => [0.22, 0.23, 0.26], Keys => [0.82, 0.82, 0.84], Door => [0.60, 0.61, 0.64], Light => [0.35, 0.90, 0.45], Metal => STEEL, Handle => STEEL, Interior => BLACK]),
    arch!("pail", bw::pail, [Metal], [Metal => [0.74, 0.76, 0.78], Interior => [0.52, 0.54, 0.56], Glass => [0.45, 0.60, 0.70], Handle => [0.55, 0.56, 0.58], Trunk => [0.55, 0.38, 0.22]]),
    arch!("cone", m::cone, [Body], [Body => [0.95, 0.45, 0.10]]),
    arch!("vehicle", m::vehicle, [Body], [Body => [0.70, 0.12, 0.10], Glass => [0.22, 0.27, 0.32]]),
    arch!("boat", m::boat, [Body], [Body => [0.50, 0.33, 0.20], Frame => [0.62, 0.47, 0.30]]),
    arch!("bicycle", m::bicycle, [Frame], [Frame => [0.15, 0.35, 0.55]]),
    arch!("figure", m::figure, [Body], [Body => [0.85, 0.83, 0.80]]),
    arch!("umbrella", m::umbrella, [Shade], [Shade => [0.85, 0.25, 0.20]]),
    arch!("pavilion", m::pavilion, [Body], [Body => WHITE, Top => [0.45, 0.30, 0.22]]),
    arch!("chest", m::chest, [Body], [Metal => [0.30, 0.28, 0.25]]),
    arch!("fence", m::fence, [Frame], [Frame => WHITE]),
    arch!("tent", st::tent, [Shade, Canvas], [Shade => [0.20, 0.45, 0.30], Canvas => [0.25, 0.50, 0.34]]),
    arch!("water", st::water, [Top], [Top => STONE, Water => [0.22, 0.45, 0.58], Interior => [0.12, 0.22, 0.26]]),
    arch!("bridge", st::bridge, [Top, Frame], [Top => [0.52, 0.36, 0.22], Frame => [0.42, 0.28, 0.17]]),
    arch!("tower", st::tower, [Body], [Frame => [0.85, 0.84, 0.80], Body => [0.85, 0.20, 0.15], Shade => [0.90, 0.88, 0.84], Metal => [0.60, 0.60, 0.62]]),
    arch!("castle", st::castle, [Body], [Body => [0.84, 0.74, 0.55], Top => [0.78, 0.66, 0.46]]),
    arch!("lantern", st::lantern, [Body, Top], [Body => STONE, Top => [0.58, 0.56, 0.52], Light => [1.0, 0.86, 0.55]]),
    arch!("brazier", bz::brazier, [Metal], [Metal => [0.17, 0.16, 0.15], Top => [0.95, 0.32, 0.08], Interior => [0.10, 0.09, 0.08], Light => [1.0, 0.72, 0.25]]),
    arch!("palm", st::palm, [Foliage], [Trunk => [0.56, 0.46, 0.34], Foliage => [0.22, 0.50, 0.18], Body => [0.36, 0.24, 0.12]]),
    arch!("tripod", t::tripod, [Body], [Body => [0.90, 0.90, 0.90], Metal => [0.20, 0.20, 0.21], Glass => [0.25, 0.35, 0.45]]),
    arch!("console", t::console, [Body, Top], [Body => [0.30, 0.32, 0.36], Top => [0.45, 0.47, 0.50]]),
    arch!("robot", t::robot, [Body], [Body => [0.78, 0.80, 0.83], Metal => [0.35, 0.36, 0.38], Light => [0.35, 0.80, 0.95]]),
    arch!("lounger", t::lounger, [Upholstery], [Upholstery => [0.92, 0.90, 0.85], Frame => [0.55, 0.40, 0.26]]),
    arch!("dispenser", t::dispenser, [Body], [Body => WHITE, Glass => [0.55, 0.72, 0.88], Handle => [0.25, 0.40, 0.80]]),
    arch!("quadruped", bs::quadruped, [Body], [Body => [0.50, 0.36, 0.24], Interior => BLACK]),
    arch!("bird", fw::bird, [Body, Frame, Top, Cushion], [Body => [0.50, 0.40, 0.30], Cushion => [0.75, 0.66, 0.52], Frame => [0.38, 0.29, 0.21], Light => [0.95, 0.75, 0.15], Handle => [0.25, 0.22, 0.20], Metal => [0.45, 0.40, 0.30]]),
    arch!("cauldron", t::cauldron, [Body], [Body => [0.16, 0.16, 0.17], Metal => [0.16, 0.16, 0.17], Water => [0.30, 0.62, 0.25]]),
    arch!("easel", t::easel, [Frame], [Frame => [0.62, 0.45, 0.28], Canvas => [0.95, 0.94, 0.90]]),
    arch!("string_instrument", t::string_instrument, [Body], [Body => [0.62, 0.36, 0.16], Frame => [0.25, 0.16, 0.10], Interior => BLACK, Metal => [0.80, 0.80, 0.78]]),
    arch!("treadmill", t::treadmill, [Body], [Body => [0.15, 0.15, 0.16], Interior => [0.05, 0.05, 0.05], Metal => [0.60, 0.61, 0.63], Screen => [0.10, 0.25, 0.35]]),
    arch!("swing", fr::swing, [Frame], [Frame => [0.55, 0.38, 0.22], Top => [0.50, 0.34, 0.20], Seat => [0.80, 0.20, 0.15], Metal => [0.55, 0.55, 0.57]]),
    arch!("slide", fr::slide, [Body], [Body => [0.95, 0.75, 0.10], Frame => [0.20, 0.45, 0.75], Top => [0.45, 0.33, 0.22]]),
    arch!("climbing_frame", fr::climbing_frame, [Frame], [Frame => [0.85, 0.25, 0.15], Metal => [0.20, 0.45, 0.75]]),
    arch!("ladder", fr::ladder, [Frame], [Frame => [0.62, 0.45, 0.28], Seat => [0.58, 0.42, 0.26], Top => [0.58, 0.42, 0.26]]),
    arch!("laptop", fr::laptop, [Body], [Body => [0.70, 0.71, 0.73], BlackKeys => [0.12, 0.12, 0.13], Interior => [0.06, 0.08, 0.12]]),
    arch!("vase", fr::vase, [Body], [Body => [0.85, 0.82, 0.76]]),
    arch!("pram", d::pram, [Body, Shade], [Body => [0.20, 0.24, 0.34], Shade => [0.20, 0.24, 0.34], Frame => [0.15, 0.15, 0.16], Metal => [0.60, 0.61, 0.63]]),
    arch!("hedge", d::hedge, [Foliage], [Foliage => [0.16, 0.40, 0.15]]),
    arch!("flower_bed", d::flower_bed, [Books], [Frame => [0.45, 0.32, 0.20], Foliage => [0.22, 0.46, 0.18]]),
    arch!("vegetable_bed", d::vegetable_bed, [Frame], [Frame => [0.45, 0.32, 0.20], Foliage => [0.30, 0.52, 0.20]]),
    arch!("log", d::log, [Trunk], [Trunk => [0.36, 0.26, 0.17], Top => [0.78, 0.62, 0.42]]),
    arch!("hydrant", d::hydrant, [Body, Top], [Body => [0.80, 0.12, 0.10], Top => [0.80, 0.12, 0.10], Metal => [0.62, 0.62, 0.64]]),
    arch!("padded_table", d::padded_table, [Upholstery], [Upholstery => [0.55, 0.70, 0.72], Frame => STEEL]),
    arch!("lectern", d::lectern, [Body, Top, Frame], [Body => [0.48, 0.31, 0.18], Top => [0.42, 0.27, 0.15], Frame => [0.42, 0.27, 0.15]]),
    arch!("globe", d::globe, [Body], [Body => [0.24, 0.44, 0.66], Foliage => [0.55, 0.62, 0.34], Frame => DARK_WOOD, Metal => [0.70, 0.58, 0.32]]),
    arch!("barrow", d::barrow, [Body], [Body => [0.35, 0.45, 0.35], Frame => [0.52, 0.38, 0.24], Top => [0.55, 0.40, 0.25], Metal => [0.45, 0.45, 0.47]]),
    arch!("house", d::house, [Body], [Body => [0.62, 0.46, 0.30], Top => [0.32, 0.28, 0.26], Door => [0.40, 0.27, 0.17], Glass => [0.55, 0.70, 0.80]]),
    arch!("greenhouse", gh::greenhouse, [Metal], [Body => [0.55, 0.36, 0.26], Metal => [0.30, 0.34, 0.32], Pane => [0.80, 0.90, 0.86], Top => [0.55, 0.40, 0.25], Frame => [0.45, 0.32, 0.20]]),
    arch!("fire_pit", he::fire_pit, [Body], [Body => STONE, Interior => [0.10, 0.09, 0.08], Trunk => [0.36, 0.26, 0.17], Light => [1.0, 0.55, 0.15]]),
    arch!("well", he::well, [Body], [Body => STONE, Top => [0.40, 0.27, 0.17], Frame => [0.45, 0.31, 0.19], Metal => [0.35, 0.33, 0.30], Interior => [0.08, 0.12, 0.14], Trunk => [0.40, 0.27, 0.17]]),
    arch!("windmill", he::windmill, [Body], [Body => [0.86, 0.82, 0.72], Top => [0.35, 0.24, 0.16], Frame => [0.40, 0.28, 0.18], Canvas => [0.93, 0.91, 0.85], Door => [0.40, 0.27, 0.17], Glass => [0.30, 0.35, 0.40]]),
    arch!("anchor", he::anchor, [Metal], [Metal => [0.20, 0.20, 0.22]]),
    arch!("cannon", he::cannon, [Metal], [Metal => [0.12, 0.12, 0.13], Trunk => [0.45, 0.30, 0.18], Tyre => [0.30, 0.20, 0.12], Interior => BLACK]),
    arch!("helm", he::helm, [Frame], [Frame => [0.50, 0.33, 0.18], Metal => [0.62, 0.50, 0.25]]),
    arch!("spinning_wheel", he::spinning_wheel, [Frame], [Frame => [0.55, 0.38, 0.22], Cushion => [0.92, 0.90, 0.84]]),
    arch!("newsstand", ss::newsstand, [Body], [Body => [0.18, 0.36, 0.26], Top => [0.14, 0.26, 0.20], Canvas => [0.95, 0.94, 0.90], Frame => [0.55, 0.56, 0.58], Interior => [0.10, 0.10, 0.11], Cushion => [0.82, 0.22, 0.14]]),
    arch!("tiki_bar", ss::tiki_bar, [Shade], [Shade => [0.72, 0.58, 0.32], Frame => [0.78, 0.66, 0.40], Body => [0.45, 0.30, 0.17], Top => [0.50, 0.33, 0.18], Glass => [0.45, 0.60, 0.42], Metal => [0.30, 0.22, 0.14], Seat => [0.55, 0.38, 0.20]]),
    arch!("street_lamp", ss::street_lamp, [Metal], [Metal => [0.12, 0.13, 0.14], Light => [1.0, 0.90, 0.62]]),
    arch!("stall", mk::stall, [Shade], [Shade => [0.80, 0.18, 0.16], Canvas => [0.95, 0.94, 0.90], Frame => [0.55, 0.40, 0.26], Body => [0.50, 0.35, 0.22], Top => [0.60, 0.44, 0.28]]),
    arch!("food_cart", vd::food_cart, [Body], [Body => [0.85, 0.86, 0.88], Metal => STEEL, Handle => [0.15, 0.15, 0.16], Tyre => [0.10, 0.10, 0.10], Frame => [0.80, 0.80, 0.82], Shade => [0.85, 0.20, 0.15], Canvas => [0.95, 0.85, 0.25]]),
    arch!("ticket_booth", vd::ticket_booth, [Body], [Body => [0.78, 0.18, 0.15], Top => [0.93, 0.92, 0.88], Glass => [0.55, 0.70, 0.78], Interior => BLACK, Canvas => [0.98, 0.85, 0.30], Frame => [0.60, 0.14, 0.12], Handle => BRASS, Shade => [0.20, 0.22, 0.30]]),
    arch!("shelter", mk::shelter, [Metal, Top], [Metal => [0.35, 0.37, 0.40], Glass => [0.62, 0.75, 0.82], Top => [0.30, 0.32, 0.35], Seat => [0.55, 0.40, 0.26], Body => [0.15, 0.35, 0.65]]),
    arch!("armour", mk::armour, [Body], [Body => STEEL, Metal => [0.55, 0.56, 0.58], Frame => DARK_WOOD, Interior => BLACK]),
    arch!("barrel", mk::barrel, [Body], [Body => [0.55, 0.38, 0.22], Top => [0.50, 0.34, 0.20], Metal => [0.25, 0.25, 0.27]]),
    arch!("grill", t::grill, [Body], [Body => [0.12, 0.12, 0.13], Metal => [0.55, 0.55, 0.57], Top => [0.45, 0.45, 0.47]]),
    arch!("wind_turbine", cr::wind_turbine, [Body], [Body => [0.93, 0.93, 0.92], Metal => [0.85, 0.85, 0.86]]),
    arch!("throne", cr::throne, [Frame], [Frame => [0.80, 0.62, 0.22], Upholstery => [0.55, 0.08, 0.12]]),
    arch!("loom", cr::loom, [Frame], [Frame => [0.55, 0.38, 0.22], Canvas => [0.93, 0.90, 0.82], Upholstery => [0.62, 0.20, 0.18], Metal => [0.50, 0.50, 0.52]]),
    arch!("trampoline", pl::trampoline, [Cushion], [Cushion => [0.15, 0.40, 0.80], Interior => [0.06, 0.06, 0.07], Metal => [0.60, 0.61, 0.63]]),
    arch!("merry_go_round", pl::merry_go_round, [Top], [Top => [0.85, 0.20, 0.15], Frame => [0.95, 0.78, 0.15], Metal => [0.20, 0.45, 0.75]]),
    arch!("surfboard", pl::surfboard, [Body], [Body => [0.95, 0.94, 0.90], Frame => [0.10, 0.55, 0.70]]),
    arch!("pool_float", pl::pool_float, [Body], [Body => [0.95, 0.40, 0.45], Cushion => WHITE]),
    arch!("goal", sp::goal, [Frame], [Frame => WHITE, Metal => [0.55, 0.56, 0.58], Canvas => [0.86, 0.87, 0.88]]),
    arch!("sports_net", sp::sports_net, [Body], [Body => [0.10, 0.10, 0.11], Canvas => WHITE, Metal => [0.16, 0.30, 0.22]]),
    arch!("diving_board", sp::diving_board, [Top], [Top => [0.20, 0.45, 0.75], Body => [0.80, 0.79, 0.76], Metal => [0.62, 0.63, 0.65]]),
    arch!("buoy", sp::buoy, [Body], [Body => [0.85, 0.15, 0.12], Canvas => WHITE, Metal => [0.30, 0.30, 0.32]]),
    arch!("stone_wall", ba::stone_wall, [Body, Top], [Body => [0.58, 0.56, 0.52], Top => [0.68, 0.66, 0.61], Interior => [0.25, 0.24, 0.22]]),
    arch!("stanchions", ba::stanchions, [Upholstery], [Upholstery => [0.55, 0.06, 0.10], Metal => [0.78, 0.64, 0.30]]),
    arch!("haystack", ba::haystack, [Body], [Body => [0.80, 0.66, 0.35], Top => [0.68, 0.54, 0.28]]),
    arch!("hoop", sp::hoop, [Metal], [Metal => [0.20, 0.21, 0.23], Body => [0.25, 0.26, 0.28], Canvas => WHITE, Frame => [0.85, 0.25, 0.12], Top => [0.95, 0.42, 0.10], Cushion => [0.92, 0.92, 0.90]]),
    arch!("rower", sp::rower, [Body], [Body => [0.12, 0.12, 0.13], Frame => [0.55, 0.56, 0.58], Metal => [0.15, 0.15, 0.16], Seat => [0.10, 0.10, 0.11], Top => [0.20, 0.20, 0.22], Handle => [0.10, 0.10, 0.11]]),
    arch!("ramp", pl::ramp, [Body], [Body => [0.75, 0.62, 0.45], Frame => [0.50, 0.36, 0.22], Top => [0.55, 0.42, 0.28], Metal => [0.60, 0.61, 0.63]]),
    arch!("dish", ut::dish, [Body], [Body => [0.90, 0.90, 0.89], Metal => [0.45, 0.46, 0.48], Handle => [0.20, 0.20, 0.21]]),
    arch!("solar_panel", ut::solar_panel, [Glass], [Glass => [0.10, 0.16, 0.34], Frame => [0.78, 0.79, 0.81], Metal => [0.55, 0.56, 0.58]]),
    arch!("gas_cylinder", ut::gas_cylinder, [Body], [Body => [0.20, 0.38, 0.62], Top => [0.90, 0.90, 0.88], Handle => [0.75, 0.60, 0.25], Metal => [0.50, 0.50, 0.52]]),
    arch!("bike_rack", ut::bike_rack, [Frame], [Frame => [0.68, 0.69, 0.71], Metal => [0.45, 0.46, 0.48]]),
    arch!("anvil", ws::anvil, [Metal], [Metal => [0.20, 0.20, 0.22], Trunk => [0.45, 0.32, 0.20], Top => [0.70, 0.55, 0.38]]),
    arch!("lathe", ws::lathe, [Body], [Body => [0.32, 0.46, 0.40], Door => [0.28, 0.40, 0.35], Top => [0.40, 0.41, 0.43], Metal => [0.70, 0.71, 0.73], Trunk => [0.72, 0.56, 0.36], Handle => [0.15, 0.15, 0.16]]),
    arch!("drill_press", ws::drill_press, [Body], [Body => [0.30, 0.36, 0.46], Top => [0.26, 0.31, 0.40], Metal => [0.72, 0.73, 0.75], Handle => [0.12, 0.12, 0.13]]),
    arch!("table_saw", ws::table_saw, [Body], [Body => [0.22, 0.23, 0.25], Top => [0.72, 0.73, 0.75], Frame => [0.85, 0.55, 0.12], Metal => [0.36, 0.37, 0.40], Glass => [0.80, 0.30, 0.15], Handle => [0.15, 0.15, 0.16]]),
    arch!("urinal", wa::urinal, [Body], [Body => WHITE, Canvas => [0.66, 0.70, 0.74], Interior => [0.40, 0.42, 0.44], Metal => STEEL]),
    arch!("pedestal_sink", wa::pedestal_sink, [Body], [Body => WHITE, Canvas => [0.82, 0.84, 0.86], Interior => [0.30, 0.30, 0.32], Metal => STEEL, Handle => STEEL]),
    arch!("font", wa::font, [Body, Top], [Body => STONE, Top => [0.58, 0.56, 0.52], Water => [0.35, 0.55, 0.66]]),
    arch!("hammock", ga::hammock, [Canvas], [Canvas => [0.85, 0.45, 0.25], Frame => [0.55, 0.38, 0.22], Metal => [0.85, 0.80, 0.68]]),
    arch!("swing_bench", ga::swing_bench, [Seat, Frame], [Seat => [0.62, 0.45, 0.28], Frame => [0.55, 0.40, 0.25], Top => [0.50, 0.36, 0.22], Metal => [0.30, 0.30, 0.32]]),
    arch!("garden_arch", ga::garden_arch, [Frame], [Frame => WHITE, Foliage => [0.20, 0.42, 0.16], Pillow => [0.80, 0.12, 0.22], Cushion => [0.95, 0.60, 0.68]]),
    arch!("harp", sc::harp, [Frame], [Frame => [0.80, 0.62, 0.25], Canvas => [0.92, 0.88, 0.78]]),
    arch!("bust", sc::bust, [Body], [Body => [0.93, 0.92, 0.89], Top => [0.70, 0.68, 0.64]]),
    arch!("altar", sc::altar, [Body], [Body => [0.80, 0.77, 0.70], Top => [0.62, 0.60, 0.56], Canvas => [0.96, 0.95, 0.92], Metal => [0.80, 0.64, 0.28], Light => [1.0, 0.86, 0.55]]),
    arch!("dishwasher", ma::dishwasher, [Body, Door], [Body => STEEL, Door => STEEL, Screen => BLACK, Handle => [0.35, 0.35, 0.37], Light => [0.35, 0.85, 0.95]]),
    arch!("microwave", ma::microwave, [Body], [Body => [0.82, 0.82, 0.83], Door => [0.16, 0.16, 0.17], Handle => [0.70, 0.70, 0.72], Keys => [0.55, 0.56, 0.58], Screen => [0.06, 0.10, 0.08]]),
    arch!("coffee_machine", ma::coffee_machine, [Body], [Body => STEEL, Metal => [0.50, 0.50, 0.52], Handle => BLACK, Interior => [0.28, 0.17, 0.09], Canvas => WHITE]),
    arch!("till", ma::till, [Body], [Body => [0.22, 0.22, 0.24], Door => [0.32, 0.32, 0.34], Keys => [0.88, 0.88, 0.86], Metal => [0.40, 0.40, 0.42], Screen => [0.10, 0.22, 0.32], Canvas => WHITE]),
    arch!("printer", ma::printer, [Body], [Body => [0.88, 0.88, 0.87], Door => [0.80, 0.80, 0.80], Top => [0.26, 0.26, 0.28], Canvas => WHITE, Screen => [0.10, 0.22, 0.32]]),
    arch!("display_case", vi::display_case, [Body], [Body => [0.55, 0.38, 0.22], Door => [0.50, 0.34, 0.20], Frame => STEEL, Interior => [0.30, 0.28, 0.26]]),
    arch!("aquarium", vi::aquarium, [Body, Top, Frame], [Body => BLACK, Door => [0.14, 0.14, 0.15], Top => BLACK, Frame => BLACK, Water => [0.16, 0.42, 0.58], Soil => [0.80, 0.72, 0.56], Foliage => [0.20, 0.55, 0.22], Pane => [0.62, 0.84, 0.90]]),
    arch!("shower", vi::shower, [Canvas], [Body => WHITE, Canvas => [0.86, 0.88, 0.90], Metal => [0.42, 0.43, 0.45], Handle => [0.42, 0.43, 0.45], Interior => [0.40, 0.40, 0.42]]),
    arch!("round_mirror", fo::round_mirror, [Frame], [Canvas => MIRROR_GLASS, Upholstery => [0.42, 0.26, 0.15]]),
    arch!("oval_mirror", fo::oval_mirror, [Frame], [Canvas => MIRROR_GLASS]),
    arch!("round_rug", fo::round_rug, [Upholstery], [Upholstery => [0.62, 0.28, 0.22], Cushion => [0.86, 0.79, 0.63]]),
    arch!("oval_rug", fo::oval_rug, [Upholstery], [Upholstery => [0.62, 0.28, 0.22], Cushion => [0.86, 0.79, 0.63]]),
    arch!("oval_table", fo::oval_table, [Top, Frame], []),
    arch!("bean_bag", se::bean_bag, [Upholstery, Cushion], [Upholstery => [0.50, 0.30, 0.45], Cushion => [0.50, 0.30, 0.45]]),
    arch!("rocking_chair", se::rocking_chair, [Frame, Seat], [Frame => [0.50, 0.33, 0.19], Seat => [0.50, 0.33, 0.19]]),
    arch!("crib", se::crib, [Frame], [Frame => WHITE, Mattress => WHITE, Duvet => [0.70, 0.82, 0.90]]),
    arch!("coat_rack", se::coat_rack, [Frame], [Frame => [0.45, 0.29, 0.16], Handle => [0.70, 0.58, 0.30], Upholstery => [0.62, 0.47, 0.30]]),
    arch!("pool_table", gm::pool_table, [Upholstery], [Upholstery => [0.08, 0.42, 0.20], Cushion => [0.06, 0.34, 0.16], Frame => [0.36, 0.20, 0.10], Body => [0.36, 0.20, 0.10], Interior => BLACK, Canvas => WHITE]),
    arch!("ping_pong_table", gm::ping_pong_table, [Top], [Top => [0.12, 0.30, 0.55], Canvas => WHITE, Interior => [0.10, 0.10, 0.11], Metal => [0.30, 0.30, 0.32]]),
    arch!("drum_kit", gm::drum_kit, [Body], [Body => [0.70, 0.10, 0.12], Canvas => [0.93, 0.92, 0.88], Metal => [0.70, 0.71, 0.73], Top => [0.82, 0.66, 0.30], Upholstery => BLACK]),
    arch!("cactus", ho::cactus, [Foliage], [Foliage => [0.30, 0.52, 0.26], Trunk => [0.20, 0.40, 0.18]]),
    arch!("teddy_bear", ho::teddy_bear, [Upholstery], [Upholstery => [0.62, 0.42, 0.24], Cushion => [0.85, 0.72, 0.55]]),
    arch!("candle", ho::candle, [Body], [Body => [0.95, 0.92, 0.82], Interior => BLACK, Metal => [0.70, 0.58, 0.32]]),
    arch!("tea_set", ho::tea_set, [Body], [Body => [0.95, 0.94, 0.90], Handle => [0.80, 0.68, 0.35], Top => [0.55, 0.38, 0.22], Interior => [0.45, 0.25, 0.10]]),
    arch!("kettle", ho::kettle, [Body], [Body => STEEL, Handle => BLACK, Glass => [0.45, 0.62, 0.75]]),
    arch!("cooking_pot", ho::cooking_pot, [Body], [Body => STEEL, Metal => STEEL, Handle => BLACK, Interior => [0.30, 0.31, 0.33]]),
    arch!("toaster", ho::toaster, [Body], [Body => STEEL, Handle => BLACK, Interior => BLACK]),
    arch!("glass_fridge", vi::glass_fridge, [Body, Door], [Body => [0.15, 0.15, 0.16], Door => [0.15, 0.15, 0.16], Interior => [0.30, 0.32, 0.34], Frame => [0.70, 0.71, 0.73], Light => [0.95, 0.96, 1.0], Handle => STEEL]),
    arch!("vending", vi::vending, [Body], [Body => [0.75, 0.12, 0.12], Interior => [0.12, 0.12, 0.13], Metal => [0.60, 0.61, 0.63], Keys => [0.85, 0.85, 0.83], Handle => [0.30, 0.30, 0.32]]),
    arch!("chandelier", hg::chandelier, [Metal], [Metal => BRASS, Body => [0.95, 0.93, 0.88], Glass => [0.86, 0.90, 0.95], Light => [1.0, 0.88, 0.60]]),
    arch!("pendant_light", hg::pendant_light, [Shade], [Shade => [0.16, 0.24, 0.22], Metal => BRASS, Light => [1.0, 0.90, 0.65]]),
    arch!("ceiling_light", hg::ceiling_light, [Metal], [Metal => [0.86, 0.86, 0.85], Light => [1.0, 0.97, 0.88]]),
    arch!("ceiling_fan", hg::ceiling_fan, [Frame], [Frame => [0.45, 0.30, 0.18], Body => [0.90, 0.90, 0.88], Metal => [0.80, 0.80, 0.80], Light => [1.0, 0.96, 0.86]]),
    arch!("banner", hg::banner, [Canvas], [Canvas => [0.58, 0.10, 0.12], Cushion => [0.86, 0.68, 0.26], Frame => DARK_WOOD, Metal => BRASS]),
    arch!("picnic_table", pc::picnic_table, [Top, Seat, Frame], [Top => [0.62, 0.47, 0.32], Seat => [0.62, 0.47, 0.32], Frame => [0.55, 0.41, 0.27]]),
    arch!("skeleton", sk::skeleton, [Body], [Body => [0.93, 0.90, 0.80], Metal => [0.30, 0.31, 0.33], Interior => BLACK]),
    arch!("square_ottoman", fo::square_ottoman, [Upholstery, Cushion], [Upholstery => [0.55, 0.45, 0.38], Cushion => [0.55, 0.45, 0.38], Frame => DARK_WOOD]),
    arch!("dumbbell_rack", gym::dumbbell_rack, [Frame], [Frame => [0.16, 0.16, 0.17], Metal => [0.10, 0.10, 0.11], Handle => STEEL]),
    arch!("yoga_mat", gym::yoga_mat, [Upholstery], [Upholstery => [0.46, 0.30, 0.62], Cushion => [0.34, 0.22, 0.47]]),
    arch!("rock", rocks::rock, [Stone], []),
    arch!("snowman", rocks::snowman, [Body], [Body => [0.96, 0.97, 0.99], Pot => [0.95, 0.50, 0.10], BlackKeys => [0.06, 0.06, 0.07], Trunk => [0.36, 0.24, 0.14], Upholstery => [0.75, 0.12, 0.12], Metal => [0.08, 0.08, 0.09]]),
    arch!("china_cabinet", gz::china_cabinet, [Body, Door, Frame], [Body => [0.42, 0.24, 0.14], Door => [0.46, 0.27, 0.16], Frame => [0.42, 0.24, 0.14], Interior => [0.55, 0.45, 0.36]]),
    arch!("phone_box", gz::phone_box, [Body, Frame, Top], [Body => [0.78, 0.09, 0.08], Frame => [0.78, 0.09, 0.08], Top => [0.74, 0.08, 0.07], Light => [0.98, 0.97, 0.92], BlackKeys => [0.10, 0.10, 0.11], Metal => [0.30, 0.30, 0.32], Handle => [0.25, 0.25, 0.27]]),
    arch!("fish_bowl", gz::fish_bowl, [Pane], [Pane => [0.66, 0.84, 0.92], Water => [0.40, 0.62, 0.78], Soil => [0.70, 0.62, 0.50], Foliage => [0.25, 0.55, 0.25]]),
    arch!("installation", sc::installation, [Top, Cushion], [Body => [0.95, 0.95, 0.94], Metal => [0.75, 0.76, 0.78], Top => [0.85, 0.15, 0.12], Cushion => [0.95, 0.75, 0.10]]),
    arch!("clothes_rack", gym::clothes_rack, [Frame], [Frame => [0.70, 0.71, 0.73], Metal => [0.55, 0.56, 0.58], Tyre => BLACK]),
    arch!("record_player", ho::record_player, [Body], [Body => [0.45, 0.29, 0.16], Metal => STEEL, BlackKeys => [0.05, 0.05, 0.06], Light => [0.85, 0.25, 0.15], Glass => [0.35, 0.35, 0.38], Handle => [0.80, 0.80, 0.78]]),
    arch!("stand_mixer", gd::stand_mixer, [Body], [Body => [0.78, 0.10, 0.12], Metal => STEEL, Handle => STEEL, Interior => [0.55, 0.56, 0.58]]),
    arch!("shredder", gd::shredder, [Metal], [Metal => [0.22, 0.22, 0.24], Top => [0.12, 0.12, 0.13], Interior => BLACK, Light => [0.35, 0.85, 0.40], Canvas => WHITE]),
    arch!("printer_3d", gd::printer_3d, [Frame], [Frame => [0.12, 0.12, 0.13], Body => [0.18, 0.18, 0.19], Top => [0.30, 0.30, 0.32], Metal => STEEL, Screen => [0.10, 0.22, 0.32], Upholstery => [0.95, 0.50, 0.10]]),
    arch!("generator", gd::generator, [Body], [Body => [0.90, 0.68, 0.10], Frame => [0.12, 0.12, 0.13], Metal => [0.45, 0.46, 0.48], Top => [0.15, 0.15, 0.16], Tyre => BLACK, Interior => BLACK, Screen => [0.05, 0.05, 0.05]]),
    arch!("radiator", gd::radiator, [Body], [Body => WHITE, Metal => STEEL, Handle => WHITE]),
    arch!("barrister_bookcase", cg::barrister_bookcase, [Body, Top, Frame], [Body => [0.42, 0.26, 0.15], Top => [0.40, 0.24, 0.14], Frame => [0.40, 0.24, 0.14], Interior => [0.20, 0.13, 0.08], Handle => BRASS]),
    arch!("freezer_case", cg::freezer_case, [Body], [Body => WHITE, Interior => [0.74, 0.84, 0.90], Frame => STEEL, Metal => [0.30, 0.31, 0.33], Light => [0.85, 0.93, 1.0], Pane => [0.80, 0.90, 0.96]]),
    arch!("fume_hood", cg::fume_hood, [Body], [Body => [0.86, 0.87, 0.86], Door => [0.80, 0.81, 0.80], Top => [0.12, 0.12, 0.13], Interior => [0.62, 0.64, 0.64], Metal => STEEL, Light => [0.95, 0.97, 1.0], Water => [0.30, 0.62, 0.85], Glass => [0.78, 0.88, 0.90], Screen => [0.10, 0.35, 0.25]]),
    arch!("terrarium", cg::terrarium, [Frame], [Frame => [0.12, 0.12, 0.13], Soil => [0.30, 0.21, 0.14], Foliage => [0.30, 0.55, 0.20], Pane => [0.82, 0.92, 0.90]]),
    arch!("crystal_ball", cg::crystal_ball, [Pane], [Pane => [0.78, 0.80, 0.96], Light => [0.72, 0.62, 1.0], Glass => [0.88, 0.90, 1.0], Trunk => [0.22, 0.13, 0.08], Metal => BRASS]),
    arch!("game_console", gi::game_console, [Body], [Body => [0.10, 0.10, 0.11], Light => [0.35, 0.65, 1.0], Interior => BLACK, BlackKeys => [0.03, 0.03, 0.03]]),
    arch!("mic_stand", gi::mic_stand, [Metal], [Metal => [0.12, 0.12, 0.13], Handle => [0.35, 0.35, 0.37], BlackKeys => [0.08, 0.08, 0.09], Canvas => [0.62, 0.63, 0.65], Tyre => BLACK]),
    arch!("blender", gi::blender, [Body], [Body => [0.80, 0.80, 0.82], Top => [0.12, 0.12, 0.13], Handle => [0.20, 0.20, 0.22], Light => [0.40, 0.80, 1.0], Water => [0.88, 0.42, 0.50], Pane => [0.84, 0.90, 0.92]]),
    arch!("rice_cooker", gi::rice_cooker, [Body], [Body => [0.94, 0.94, 0.93], Top => [0.88, 0.88, 0.88], Handle => [0.40, 0.40, 0.42], Metal => [0.55, 0.56, 0.58], Light => [0.95, 0.60, 0.25]]),
    arch!("birdcage", gi::birdcage, [Metal, Body], [Metal => BRASS, Body => BRASS, Trunk => [0.55, 0.40, 0.25], Handle => [0.95, 0.55, 0.10]]),
    arch!("forklift", rigs::forklift, [Body], [Body => [0.95, 0.72, 0.08], Metal => [0.22, 0.22, 0.24], Frame => [0.12, 0.12, 0.13], Seat => [0.10, 0.10, 0.11], Handle => STEEL, Light => [1.0, 0.62, 0.12], Tyre => BLACK]),
    arch!("staff", rigs::staff, [Trunk], [Trunk => [0.42, 0.29, 0.17], Metal => [0.15, 0.15, 0.16], Light => [0.45, 0.80, 1.0]]),
    arch!("pod", rigs::pod, [Body], [Body => [0.90, 0.91, 0.92], Frame => [0.25, 0.26, 0.28], Light => [0.35, 0.90, 1.0], Pane => [0.78, 0.92, 0.98], Canvas => [0.55, 0.65, 0.75], Metal => [0.45, 0.46, 0.48], Door => [0.80, 0.81, 0.82], Glass => [0.40, 0.70, 0.85]]),
    arch!("music_stand", sd::music_stand, [Metal], [Metal => [0.10, 0.10, 0.11], Canvas => [0.96, 0.94, 0.88], BlackKeys => [0.15, 0.15, 0.16]]),
    arch!("iv_stand", sd::iv_stand, [Metal], [Metal => STEEL, Tyre => BLACK, Pane => [0.88, 0.92, 0.95], Water => [0.82, 0.90, 0.96], Canvas => [0.90, 0.92, 0.94], Body => [0.90, 0.90, 0.88], Screen => [0.10, 0.30, 0.22]]),
    arch!("traffic_light", sd::traffic_light, [Body], [Body => [0.12, 0.12, 0.13], Frame => [0.25, 0.26, 0.27], Light => [0.95, 0.12, 0.08], Top => [1.0, 0.68, 0.05], Seat => [0.10, 0.85, 0.35]]),
    arch!("gramophone", sd::gramophone, [Metal], [Metal => BRASS, Trunk => [0.40, 0.22, 0.12], Frame => [0.30, 0.17, 0.09], Interior => [0.35, 0.25, 0.12]]),
    arch!("headstone", mr::headstone, [Body], [Body => [0.58, 0.58, 0.56], Stone => [0.50, 0.49, 0.46], Interior => [0.22, 0.22, 0.22]]),
    arch!("flagpole", mr::flagpole, [Upholstery], [Upholstery => [0.80, 0.12, 0.14], Cushion => [0.95, 0.95, 0.94], Metal => [0.78, 0.79, 0.80], Handle => [0.85, 0.70, 0.30], Stone => [0.62, 0.62, 0.60]]),
    arch!("portable_toilet", mr::portable_toilet, [Body, Door], [Body => [0.15, 0.38, 0.72], Door => [0.17, 0.42, 0.78], Top => [0.92, 0.92, 0.90], Frame => [0.25, 0.25, 0.27], Metal => [0.30, 0.30, 0.32], Handle => [0.85, 0.85, 0.85], Seat => [0.15, 0.75, 0.30], Interior => [0.08, 0.10, 0.14]]),
    arch!("projector", mr::projector, [Body], [Body => [0.90, 0.90, 0.90], Metal => [0.25, 0.25, 0.27], Glass => [0.15, 0.20, 0.28], Interior => [0.30, 0.30, 0.32], Light => [0.35, 0.80, 1.0]]),
    arch!("towel_rack", rk::towel_rack, [Metal], [Metal => STEEL, Canvas => [0.93, 0.92, 0.88], Cushion => [0.45, 0.62, 0.72]]),
    arch!("wine_rack", rk::wine_rack, [Frame, Top], [Frame => [0.55, 0.38, 0.22], Top => [0.50, 0.34, 0.20], Interior => [0.20, 0.13, 0.08], Glass => [0.14, 0.30, 0.16], BlackKeys => [0.30, 0.08, 0.10]]),
    arch!("pantry_rack", rk::pantry_rack, [Frame, Top], [Frame => [0.62, 0.47, 0.30], Top => [0.66, 0.50, 0.32], Pane => [0.85, 0.92, 0.92], Metal => [0.78, 0.72, 0.55]]),
    arch!("weapon_rack", rk::weapon_rack, [Frame], [Frame => [0.45, 0.30, 0.17], Trunk => [0.52, 0.38, 0.24], Metal => [0.74, 0.75, 0.78], Handle => [0.62, 0.50, 0.25]]),
    arch!("trash_can", bn::trash_can, [Body], [Body => STEEL, Top => [0.50, 0.51, 0.53], Metal => [0.55, 0.56, 0.58], Handle => [0.12, 0.12, 0.13], Tyre => [0.12, 0.12, 0.13]]),
    arch!("umbrella_stand", bn::umbrella_stand, [Body], [Body => [0.30, 0.40, 0.50], Interior => [0.10, 0.10, 0.11], Metal => [0.40, 0.40, 0.42], Handle => [0.30, 0.19, 0.10]]),
    arch!("weight_bench", tr::weight_bench, [Upholstery], [Upholstery => [0.10, 0.10, 0.11], Frame => [0.20, 0.20, 0.22], Metal => [0.12, 0.12, 0.13], Handle => STEEL]),
    arch!("punching_bag", tr::punching_bag, [Upholstery], [Upholstery => [0.62, 0.10, 0.10], Cushion => [0.10, 0.10, 0.11], Frame => [0.18, 0.18, 0.20], Metal => [0.62, 0.63, 0.65]]),
    arch!("exercise_bike", tr::exercise_bike, [Frame], [Frame => [0.20, 0.20, 0.22], Metal => [0.55, 0.56, 0.58], Upholstery => [0.10, 0.10, 0.11], Seat => [0.12, 0.12, 0.13], Tyre => [0.75, 0.12, 0.10]]),
    arch!("chaise", lo::chaise, [Upholstery, Cushion], [Frame => DARK_WOOD, Pillow => [0.80, 0.74, 0.62]]),
    arch!("egg_chair", lo::egg_chair, [Upholstery, Cushion], [Body => WHITE, Metal => STEEL, Upholstery => [0.20, 0.30, 0.45], Cushion => [0.22, 0.33, 0.48]]),
    arch!("papasan", lo::papasan, [Cushion], [Frame => [0.72, 0.55, 0.33], Cushion => [0.82, 0.76, 0.64]]),
    arch!("hanging_chair", lo::hanging_chair, [Frame], [Frame => [0.70, 0.54, 0.33], Metal => [0.20, 0.20, 0.21], Cushion => [0.92, 0.90, 0.84]]),
    arch!("recliner", lo::recliner, [Upholstery, Cushion], [Upholstery => [0.36, 0.24, 0.16], Cushion => [0.40, 0.27, 0.18], Metal => [0.25, 0.25, 0.27]]),
    arch!("nesting_tables", sx::nesting_tables, [Top, Frame], []),
    arch!("pallet", sx::pallet, [Top, Frame], [Top => [0.74, 0.60, 0.42], Frame => [0.64, 0.50, 0.34]]),
    arch!("murphy_bed", sx::murphy_bed, [Body, Door, Top], [Mattress => [0.90, 0.88, 0.84], Metal => [0.30, 0.30, 0.32]]),
    arch!("snake_plant", pt::snake_plant, [Foliage], [Foliage => [0.16, 0.36, 0.18], Pot => [0.88, 0.87, 0.84]]),
    arch!("fern", pt::fern, [Foliage], [Foliage => [0.30, 0.56, 0.20], Trunk => [0.26, 0.40, 0.16]]),
    arch!("bamboo", pt::bamboo, [Foliage], [Trunk => [0.55, 0.64, 0.26], Foliage => [0.28, 0.55, 0.20], Pot => [0.20, 0.22, 0.24]]),
    arch!("orchid", pt::orchid, [Canvas], [Canvas => [0.97, 0.96, 0.97], Pillow => [0.85, 0.35, 0.55], Foliage => [0.18, 0.42, 0.18], Pot => [0.90, 0.90, 0.88], Trunk => [0.35, 0.40, 0.22]]),
    arch!("bonsai", pt::bonsai, [Foliage], [Foliage => [0.18, 0.42, 0.16], Trunk => [0.40, 0.30, 0.22], Pot => [0.34, 0.24, 0.20]]),
    arch!("hanging_plant", pt::hanging_plant, [Foliage], [Foliage => [0.24, 0.52, 0.20], Frame => [0.85, 0.80, 0.68], Pot => [0.88, 0.86, 0.82]]),
    arch!("cart", ca::cart, [Metal, Frame], [Metal => BRASS, Frame => BRASS, Top => [0.20, 0.20, 0.21], Handle => BRASS, Tyre => BLACK, Glass => [0.20, 0.36, 0.22], BlackKeys => [0.45, 0.16, 0.08], Pane => [0.85, 0.92, 0.95], Canvas => [0.70, 0.55, 0.33]]),
    arch!("airer", ca::airer, [Frame], [Frame => [0.88, 0.88, 0.87], Metal => [0.80, 0.80, 0.80]]),
    arch!("wall_clock", ck::wall_clock, [Frame], [Frame => [0.12, 0.12, 0.13], Canvas => [0.96, 0.96, 0.94], BlackKeys => BLACK]),
    arch!("grandfather_clock", ck::grandfather_clock, [Body, Door, Frame], [Body => [0.36, 0.20, 0.11], Door => [0.38, 0.21, 0.12], Frame => [0.30, 0.17, 0.09], Top => [0.80, 0.66, 0.35], Canvas => [0.95, 0.92, 0.84], Metal => BRASS, Handle => BRASS, Interior => [0.08, 0.06, 0.05], BlackKeys => BLACK]),
    arch!("wheelchair", cw::wheelchair, [Upholstery], [Upholstery => [0.10, 0.10, 0.11], Frame => [0.70, 0.71, 0.73], Metal => STEEL, Tyre => BLACK, Handle => BLACK]),
    arch!("high_chair", cw::high_chair, [Frame, Seat], [Frame => [0.70, 0.52, 0.32], Seat => [0.72, 0.54, 0.34], Cushion => [0.55, 0.75, 0.82], Top => WHITE]),
    arch!("hospital_bed", sl::hospital_bed, [Frame, Body], [Frame => [0.78, 0.79, 0.80], Body => [0.88, 0.90, 0.90], Mattress => [0.45, 0.66, 0.74], Duvet => [0.92, 0.93, 0.95], Pillow => WHITE, Metal => STEEL, Tyre => BLACK, Top => [0.80, 0.82, 0.84], Screen => [0.15, 0.25, 0.30]]),
    arch!("cabin_bed", sl::cabin_bed, [Frame], [Frame => [0.93, 0.92, 0.90], Body => [0.93, 0.92, 0.90], Door => [0.88, 0.88, 0.86], Duvet => [0.40, 0.55, 0.75], Mattress => [0.85, 0.85, 0.82], Pillow => WHITE, Handle => STEEL, Top => [0.78, 0.62, 0.42]]),
    arch!("barber_chair", sa::barber_chair, [Upholstery], [Upholstery => [0.50, 0.08, 0.08], Metal => [0.80, 0.81, 0.83], Body => WHITE, Frame => DARK_WOOD, Handle => [0.20, 0.20, 0.21]]),
    arch!("dentist_chair", sa::dentist_chair, [Upholstery, Cushion], [Upholstery => [0.35, 0.65, 0.70], Cushion => [0.33, 0.62, 0.67], Body => WHITE, Metal => STEEL, Light => [1.0, 0.96, 0.85], Top => [0.85, 0.86, 0.87], Canvas => WHITE, Water => [0.50, 0.70, 0.85], Handle => STEEL]),
    arch!("magazine_stand", dp::magazine_stand, [Frame, Top], [Frame => [0.22, 0.22, 0.24], Top => [0.30, 0.30, 0.32], Canvas => WHITE]),
    arch!("file_sorter", dp::file_sorter, [Frame], [Frame => [0.16, 0.16, 0.17], Canvas => WHITE]),
    arch!("patient_chair", rc::patient_chair, [Upholstery, Cushion], [Upholstery => [0.30, 0.45, 0.60], Cushion => [0.28, 0.42, 0.57], Body => [0.85, 0.86, 0.87], Metal => STEEL]),
    arch!("tattoo_chair", rc::tattoo_chair, [Upholstery, Cushion], [Upholstery => [0.10, 0.10, 0.11], Cushion => [0.12, 0.12, 0.13], Body => [0.25, 0.25, 0.27], Metal => STEEL]),
    arch!("hood_dryer_chair", sa::hood_dryer_chair, [Upholstery, Cushion], [Upholstery => [0.55, 0.18, 0.30], Frame => DARK_WOOD, Body => [0.90, 0.90, 0.91], Metal => STEEL, Interior => [0.15, 0.15, 0.16]]),
    arch!("pedicure_chair", sa::pedicure_chair, [Upholstery], [Upholstery => [0.30, 0.20, 0.15], Cushion => [0.34, 0.23, 0.17], Body => [0.12, 0.12, 0.13], Top => [0.80, 0.78, 0.74], Canvas => WHITE, Water => [0.45, 0.70, 0.85], Metal => STEEL, Frame => [0.25, 0.25, 0.26]]),
    arch!("magazine_rack", hr::magazine_rack, [Frame], [Frame => [0.62, 0.47, 0.30]]),
    arch!("shoe_rack", hr::shoe_rack, [Frame, Top], [Frame => [0.55, 0.38, 0.22], Top => [0.58, 0.41, 0.25], Interior => [0.12, 0.12, 0.12]]),
    arch!("plate_rack", hr::plate_rack, [Frame], [Frame => [0.62, 0.47, 0.30], Canvas => WHITE, Pot => [0.30, 0.45, 0.70]]),
    arch!("book_cart", hr::book_cart, [Frame, Top], [Frame => [0.55, 0.38, 0.22], Top => [0.58, 0.41, 0.25], Metal => [0.20, 0.20, 0.21], Tyre => BLACK]),
    arch!("church_organ", ins::church_organ, [Body, Top], [Body => [0.40, 0.25, 0.14], Top => [0.36, 0.22, 0.12], Metal => [0.80, 0.80, 0.78], Interior => [0.10, 0.07, 0.05], Keys => [0.95, 0.93, 0.88], BlackKeys => BLACK, Handle => [0.90, 0.88, 0.82], Frame => [0.42, 0.27, 0.15], Seat => [0.40, 0.25, 0.14]]),
    arch!("bowed_instrument", ins::bowed_instrument, [Body], [Body => [0.55, 0.28, 0.12], Frame => [0.48, 0.26, 0.12], BlackKeys => BLACK, Interior => BLACK, Top => [0.85, 0.72, 0.50], Metal => [0.55, 0.53, 0.48], Trunk => BLACK, Canvas => [0.92, 0.90, 0.84]]),
    arch!("folding_screen", pn::folding_screen, [Frame], [Frame => [0.45, 0.30, 0.17], Canvas => [0.92, 0.88, 0.78], Upholstery => [0.50, 0.34, 0.20], Metal => BRASS]),
    arch!("van", ve::van, [Body], [Body => WHITE, Glass => [0.22, 0.27, 0.32], Frame => [0.15, 0.15, 0.16], Interior => [0.12, 0.12, 0.13], Light => [1.0, 0.95, 0.80]]),
    arch!("bus", ve::bus, [Body], [Body => [0.78, 0.10, 0.10], Top => [0.90, 0.90, 0.89], Glass => [0.20, 0.25, 0.30], Frame => [0.15, 0.15, 0.16], Door => [0.18, 0.18, 0.20], Light => [1.0, 0.80, 0.30]]),
    arch!("food_truck", tt::food_truck, [Body], [Body => [0.95, 0.72, 0.18], Canvas => [0.80, 0.18, 0.15], Top => [0.78, 0.79, 0.80], Glass => [0.22, 0.27, 0.32], Frame => [0.15, 0.15, 0.16], Interior => [0.10, 0.09, 0.08], Metal => [0.70, 0.71, 0.72], Light => [1.0, 0.93, 0.70]]),
    arch!("tram", tt::tram, [Body], [Body => [0.75, 0.12, 0.12], Top => [0.90, 0.88, 0.80], Glass => [0.20, 0.25, 0.30], Frame => [0.15, 0.15, 0.16], Pane => [0.80, 0.78, 0.70], Metal => [0.35, 0.36, 0.38], Light => [1.0, 0.85, 0.40]]),
    arch!("sauna_stove", ov::sauna_stove, [Body], [Body => [0.10, 0.10, 0.11], Door => [0.14, 0.14, 0.15], Metal => [0.22, 0.22, 0.23], Stone => [0.50, 0.50, 0.50], Light => [1.0, 0.55, 0.15]]),
    arch!("wood_stove", ov::wood_stove, [Body], [Body => [0.09, 0.09, 0.10], Top => [0.13, 0.13, 0.14], Door => [0.16, 0.16, 0.17], Metal => [0.12, 0.12, 0.13], Interior => [0.35, 0.12, 0.04], Light => [1.0, 0.58, 0.18]]),
    arch!("pizza_oven", ov::pizza_oven, [Body], [Body => [0.66, 0.36, 0.24], Stone => [0.62, 0.60, 0.57], Top => [0.72, 0.70, 0.66], Frame => [0.50, 0.24, 0.16], Interior => [0.06, 0.05, 0.05], Trunk => [0.45, 0.30, 0.18], Light => [1.0, 0.55, 0.15], Metal => [0.20, 0.20, 0.21]]),
    arch!("pickup", ve::pickup, [Body], [Body => [0.20, 0.30, 0.55], Glass => [0.22, 0.27, 0.32], Frame => [0.15, 0.15, 0.16], Interior => [0.10, 0.10, 0.11], Light => [1.0, 0.95, 0.80]]),
    arch!("lorry", ve::lorry, [Canvas], [Body => [0.75, 0.12, 0.10], Canvas => [0.93, 0.93, 0.92], Glass => [0.22, 0.27, 0.32], Frame => [0.12, 0.12, 0.13], Interior => [0.10, 0.10, 0.11], Metal => [0.55, 0.56, 0.58], Light => [1.0, 0.95, 0.80]]),
    arch!("air_conditioner", fx::air_conditioner, [Body, Door], [Body => WHITE, Door => [0.88, 0.88, 0.89], Metal => [0.86, 0.86, 0.87], Frame => [0.70, 0.70, 0.72], Interior => [0.14, 0.14, 0.15], Screen => [0.10, 0.12, 0.14], Light => [0.35, 0.75, 1.0]]),
    arch!("range_hood", fx::range_hood, [Body, Metal], [Body => STEEL, Metal => STEEL, Frame => [0.50, 0.51, 0.53], Interior => [0.15, 0.15, 0.16], Light => [1.0, 0.95, 0.80], Handle => BLACK]),
    arch!("kiln", fx::kiln, [Body], [Body => [0.76, 0.77, 0.79], Metal => [0.42, 0.43, 0.45], Top => [0.68, 0.69, 0.71], Frame => [0.18, 0.18, 0.20], Screen => [0.14, 0.14, 0.15], Light => [0.95, 0.35, 0.15], Handle => [0.28, 0.28, 0.30], Interior => BLACK]),
    arch!("microscope", sco::microscope, [Body], [Body => [0.93, 0.93, 0.91], Metal => STEEL, Top => BLACK, Handle => [0.16, 0.16, 0.17], BlackKeys => BLACK, Light => [1.0, 0.95, 0.80]]),
    arch!("softbox", sco::softbox, [Body], [Body => [0.08, 0.08, 0.09], Metal => [0.16, 0.16, 0.17], Frame => [0.12, 0.12, 0.13], Handle => [0.22, 0.22, 0.24], Light => [0.97, 0.97, 0.95], Tyre => BLACK]),
    arch!("spotlight", sco::spotlight, [Body], [Body => BLACK, Metal => [0.16, 0.16, 0.17], Frame => [0.12, 0.12, 0.13], Handle => [0.22, 0.22, 0.24], Light => [1.0, 0.95, 0.75], Interior => BLACK, Tyre => BLACK]),
    arch!("foosball", pa::foosball, [Body], [Body => [0.55, 0.38, 0.22], Frame => DARK_WOOD, Canvas => [0.20, 0.55, 0.25], Cushion => WHITE, Metal => STEEL, Handle => BLACK, Upholstery => [0.80, 0.12, 0.10], Seat => [0.12, 0.25, 0.70], Skin => [0.90, 0.75, 0.60], Interior => BLACK]),
    arch!("roulette", pa::roulette, [Canvas], [Canvas => [0.10, 0.42, 0.22], Frame => [0.40, 0.22, 0.12], Cushion => WHITE, Foliage => [0.10, 0.60, 0.25], Upholstery => [0.78, 0.10, 0.10], BlackKeys => BLACK, Top => [0.55, 0.35, 0.18], Metal => BRASS]),
    arch!("gnome", yd::gnome, [Upholstery], [Body => [0.20, 0.35, 0.70], Upholstery => [0.82, 0.12, 0.10], Canvas => [0.96, 0.96, 0.95], Skin => [0.95, 0.76, 0.62], BlackKeys => [0.25, 0.16, 0.09], Frame => [0.25, 0.16, 0.09], Metal => BRASS]),
    arch!("seesaw", yd::seesaw, [Top], [Top => [0.95, 0.72, 0.10], Frame => [0.20, 0.45, 0.75], Metal => STEEL, Seat => [0.80, 0.12, 0.10], Handle => [0.15, 0.15, 0.16]]),
    arch!("lawn_mower", yd::lawn_mower, [Body], [Body => [0.80, 0.12, 0.10], Frame => [0.20, 0.20, 0.22], Top => BLACK, Canvas => [0.25, 0.25, 0.27], Metal => [0.16, 0.16, 0.17], Handle => BLACK, Tyre => BLACK]),
    arch!("shopping_cart", yd::shopping_cart, [Metal], [Metal => STEEL, Frame => [0.62, 0.63, 0.65], Handle => [0.80, 0.12, 0.10], Tyre => BLACK]),
    arch!("lighthouse", co::lighthouse, [Upholstery], [Body => WHITE, Upholstery => [0.80, 0.12, 0.10], Stone => STONE, Door => [0.20, 0.25, 0.30], Interior => BLACK, Frame => [0.15, 0.15, 0.16], Metal => [0.15, 0.15, 0.16], Glass => [0.75, 0.85, 0.90], Light => [1.0, 0.90, 0.55], Top => [0.80, 0.12, 0.10]]),
    arch!("mast", co::mast, [Canvas], [Trunk => [0.45, 0.30, 0.17], Canvas => [0.93, 0.90, 0.80], Frame => [0.40, 0.27, 0.15], BlackKeys => [0.15, 0.12, 0.10], Upholstery => [0.80, 0.12, 0.10]]),
    arch!("fruit_tree", oc::fruit_tree, [Skin], [Skin => [0.80, 0.10, 0.10], Foliage => [0.25, 0.50, 0.18], Trunk => [0.35, 0.24, 0.15]]),
    arch!("blossom_tree", oc::blossom_tree, [Foliage], [Foliage => [0.96, 0.70, 0.80], Cushion => [0.99, 0.90, 0.93], Trunk => [0.25, 0.16, 0.12]]),
    arch!("speaker", au::speaker, [Body], [Body => DARK_WOOD, Interior => [0.06, 0.06, 0.07], Handle => [0.75, 0.12, 0.10]]),
    arch!("headphones", au::headphones, [Frame, Body], [Frame => [0.10, 0.10, 0.11], Body => [0.12, 0.12, 0.13], Cushion => [0.20, 0.20, 0.21], Metal => [0.70, 0.71, 0.73]]),
    arch!("headset", au::headset, [Frame, Body], [Frame => [0.10, 0.10, 0.11], Body => [0.12, 0.12, 0.13], Cushion => [0.20, 0.20, 0.21], Metal => [0.70, 0.71, 0.73]]),
    arch!("amp_combo", au::amp_combo, [Body], [Body => [0.10, 0.10, 0.10], Upholstery => [0.46, 0.45, 0.43], Canvas => [0.85, 0.80, 0.65], Metal => [0.78, 0.78, 0.80], Handle => [0.08, 0.08, 0.08], Frame => [0.12, 0.10, 0.09], Light => [0.95, 0.15, 0.10]]),
    arch!("server_rack", sv::server_rack, [Body, Frame], [Body => [0.07, 0.07, 0.08], Frame => [0.10, 0.10, 0.11], Metal => [0.22, 0.22, 0.24], Pane => [0.10, 0.10, 0.11], Light => [0.30, 0.95, 0.45], Handle => [0.30, 0.60, 1.00], Canvas => [0.15, 0.35, 0.75]]),
    arch!("coat_hooks", pg::coat_hooks, [Top], [Top => DARK_WOOD, Metal => BRASS, Frame => [0.45, 0.28, 0.16], Cushion => [0.25, 0.22, 0.20]]),
    arch!("pegboard", pg::pegboard, [Top], [Top => [0.66, 0.52, 0.36], Interior => [0.20, 0.15, 0.10], Metal => [0.60, 0.61, 0.63], Frame => [0.55, 0.36, 0.20], Handle => [0.80, 0.15, 0.10]]),
    arch!("canoe_rack", bt::canoe_rack, [Frame], [Frame => [0.50, 0.36, 0.22], Cushion => [0.15, 0.15, 0.16], Body => [0.75, 0.16, 0.12], Upholstery => [0.95, 0.72, 0.10]]),
    arch!("oar", bt::oar, [Frame, Top], [Frame => [0.70, 0.52, 0.30], Top => [0.70, 0.52, 0.30], Upholstery => [0.30, 0.20, 0.12], Handle => [0.60, 0.44, 0.26]]),
    arch!("fishing_rod", bt::fishing_rod, [Frame], [Frame => [0.12, 0.14, 0.18], Cushion => [0.72, 0.56, 0.36], Metal => [0.70, 0.71, 0.73], Handle => [0.15, 0.15, 0.16], Canvas => [0.92, 0.92, 0.90]]),
    arch!("luggage_cart", bh::luggage_cart, [Metal], [Metal => BRASS, Upholstery => [0.55, 0.12, 0.12], Tyre => BLACK]),
    arch!("luggage_rack", bh::luggage_rack, [Frame], [Frame => DARK_WOOD, Upholstery => [0.12, 0.12, 0.13], Metal => BRASS]),
    arch!("clothes_valet", bh::clothes_valet, [Frame], [Frame => DARK_WOOD, Top => DARK_WOOD, Canvas => WHITE]),
    arch!("beer_tap", tp::beer_tap, [Metal], [Metal => [0.80, 0.80, 0.82], Interior => [0.25, 0.25, 0.27], Handle => [0.10, 0.10, 0.10], Canvas => [0.92, 0.92, 0.90]]),
    arch!("compressor", tk::compressor, [Body], [Body => [0.78, 0.12, 0.10], Frame => [0.15, 0.15, 0.16], Metal => [0.62, 0.63, 0.65], Handle => [0.15, 0.15, 0.16], Tyre => BLACK]),
    arch!("silo", tk::silo, [Body], [Body => [0.72, 0.74, 0.76], Metal => [0.58, 0.60, 0.62], Top => [0.62, 0.64, 0.66], Frame => [0.40, 0.41, 0.43], Stone => [0.62, 0.61, 0.58]]),
    arch!("reactor_core", tk::reactor_core, [Light], [Light => [0.35, 0.85, 1.00], Metal => [0.55, 0.57, 0.60], Frame => [0.22, 0.23, 0.25], Handle => [0.80, 0.60, 0.15]]),
    arch!("sundial", or::sundial, [Body], [Body => STONE, Stone => [0.60, 0.58, 0.54], Metal => [0.55, 0.42, 0.22], BlackKeys => [0.20, 0.15, 0.08]]),
    arch!("totem_pole", or::totem_pole, [Body], [Body => [0.52, 0.34, 0.20], Door => [0.10, 0.45, 0.45], Handle => [0.70, 0.15, 0.10], Canvas => [0.92, 0.90, 0.85]]),
    arch!("tree_stump", or::tree_stump, [Trunk], [Top => [0.78, 0.62, 0.42], Frame => [0.58, 0.42, 0.26], Interior => [0.25, 0.17, 0.10], Foliage => [0.30, 0.45, 0.18]]),
    arch!("fruit_bowl", bw::fruit_bowl, [Body], [Body => WHITE, Top => [0.88, 0.88, 0.86], Trunk => [0.30, 0.22, 0.12]]),
    arch!("pet_bowl", bw::pet_bowl, [Metal], [Metal => STEEL, Tyre => BLACK, Soil => [0.50, 0.30, 0.15]]),
    arch!("laundry_basket", bw::laundry_basket, [Body], [Body => [0.78, 0.66, 0.46], Frame => [0.62, 0.50, 0.32], Interior => [0.45, 0.36, 0.24]]),
    arch!("water_jug", bw::water_jug, [Glass], [Glass => [0.55, 0.75, 0.92], Handle => [0.15, 0.35, 0.80], Interior => [0.40, 0.60, 0.80]]),
    arch!("flower_bucket_stand", fl::flower_bucket_stand, [Frame], [Frame => [0.40, 0.30, 0.20], Top => [0.48, 0.36, 0.24], Metal => [0.66, 0.68, 0.70], Foliage => [0.22, 0.45, 0.20]]),
    arch!("flower_bucket", fl::flower_bucket, [Metal], [Metal => [0.66, 0.68, 0.70], Foliage => [0.22, 0.45, 0.20], Interior => [0.10, 0.12, 0.10]]),
    arch!("bollard", tk::bollard, [Body, Top], [Body => [0.25, 0.25, 0.27], Top => [0.25, 0.25, 0.27], Metal => [0.30, 0.30, 0.32], Frame => [0.55, 0.56, 0.58], Canvas => [0.95, 0.78, 0.10]]),
    arch!("stage", pd::stage, [Top], [Top => [0.24, 0.21, 0.19], Body => [0.30, 0.29, 0.29], Frame => [0.55, 0.40, 0.26], Canvas => [0.06, 0.06, 0.07], Handle => [0.85, 0.75, 0.25]]),
    arch!("pedestal", pd::pedestal, [Body, Top, Frame], [Body => WHITE, Top => WHITE, Frame => [0.84, 0.84, 0.83], Interior => [0.45, 0.45, 0.46]]),
    arch!("hostess_stand", pd::hostess_stand, [Body, Top], [Body => DARK_WOOD, Top => [0.36, 0.23, 0.13], Door => [0.34, 0.21, 0.12], Frame => [0.18, 0.12, 0.08], Interior => [0.10, 0.07, 0.05], Metal => BRASS, Shade => [0.12, 0.30, 0.18], Canvas => [0.38, 0.10, 0.09]]),
    arch!("jewelry_armoire", dr::jewelry_armoire, [Body, Top, Door], [Body => [0.42, 0.22, 0.14], Top => [0.42, 0.22, 0.14], Door => [0.46, 0.25, 0.16], Frame => [0.36, 0.19, 0.12], Handle => BRASS, Glass => [0.80, 0.86, 0.90]]),
    arch!("examination_lamp", wd::examination_lamp, [Shade], [Shade => [0.90, 0.91, 0.92], Metal => [0.80, 0.81, 0.83], Frame => [0.55, 0.56, 0.58], Light => [1.0, 0.97, 0.88], Handle => [0.35, 0.55, 0.75], Tyre => BLACK]),
    arch!("dog_bed", pe::dog_bed, [Upholstery], [Upholstery => [0.55, 0.42, 0.32], Cushion => [0.90, 0.85, 0.76]]),
    arch!("cat_tree", pe::cat_tree, [Upholstery], [Upholstery => [0.72, 0.68, 0.62], Frame => [0.80, 0.68, 0.46], Trunk => [0.66, 0.54, 0.34], Interior => [0.12, 0.11, 0.10], Handle => [0.85, 0.20, 0.15], Metal => [0.30, 0.30, 0.30]]),
    arch!("workbench", wt::workbench, [Top, Frame], [Top => [0.72, 0.55, 0.34], Frame => [0.50, 0.36, 0.22], Body => [0.80, 0.12, 0.10], Handle => BLACK, Metal => [0.35, 0.36, 0.38]]),
    arch!("drafting_table", wt::drafting_table, [Top], [Top => [0.88, 0.86, 0.80], Frame => [0.55, 0.40, 0.26], Canvas => [0.97, 0.97, 0.95], Metal => [0.65, 0.66, 0.68]]),
    arch!("ironing_board", wt::ironing_board, [Canvas], [Canvas => [0.55, 0.70, 0.85], Frame => [0.80, 0.80, 0.82], Metal => [0.75, 0.76, 0.78], Tyre => BLACK, Body => [0.90, 0.90, 0.92], Handle => [0.20, 0.45, 0.80]]),
    arch!("lockers", lk::lockers, [Body, Door], [Body => [0.28, 0.42, 0.60], Door => [0.30, 0.45, 0.64], Interior => [0.10, 0.11, 0.13], Handle => [0.80, 0.80, 0.82], Canvas => [0.92, 0.92, 0.90]]),
    arch!("canopy_bed", cb::canopy_bed, [Duvet], [Duvet => [0.86, 0.82, 0.74], Canvas => [0.95, 0.93, 0.88], Frame => DARK_WOOD]),
    arch!("bassinet", nu::bassinet, [Body, Shade], [Body => [0.93, 0.92, 0.90], Shade => [0.93, 0.92, 0.90], Mattress => [0.98, 0.97, 0.95], Pillow => [0.80, 0.88, 0.95], Frame => [0.75, 0.62, 0.45]]),
    arch!("cradle", nu::cradle, [Frame, Top], [Frame => [0.66, 0.48, 0.30], Top => [0.66, 0.48, 0.30], Mattress => [0.96, 0.95, 0.92], Pillow => [0.95, 0.90, 0.80]]),
    arch!("rocking_horse", nu::rocking_horse, [Body], [Body => [0.72, 0.52, 0.32], Frame => [0.50, 0.34, 0.20], Seat => [0.75, 0.12, 0.12], Interior => BLACK, Cushion => [0.16, 0.11, 0.07]]),
    arch!("spring_rider", rd::spring_rider, [Body], [Body => [0.85, 0.20, 0.15], Metal => [0.95, 0.78, 0.12], Frame => [0.35, 0.36, 0.38], Handle => [0.12, 0.12, 0.13], Interior => BLACK, Cushion => [0.95, 0.85, 0.30]]),
    arch!("fossil", fos::dinosaur_skeleton, [Body], [Body => [0.80, 0.72, 0.58], Metal => [0.25, 0.26, 0.28], Stone => [0.22, 0.22, 0.23], Interior => [0.20, 0.16, 0.12]]),
    arch!("birdhouse", po::birdhouse, [Body], [Body => [0.62, 0.45, 0.28], Top => [0.45, 0.22, 0.16], Trunk => [0.40, 0.30, 0.20], Metal => [0.30, 0.30, 0.32], Interior => BLACK]),
    arch!("bird_feeder", po::bird_feeder, [Top], [Top => [0.25, 0.40, 0.25], Frame => [0.25, 0.25, 0.27], Metal => [0.25, 0.25, 0.27], Soil => [0.78, 0.66, 0.42], Pane => [0.85, 0.90, 0.92]]),
    arch!("patio_heater", po::patio_heater, [Body, Shade], [Body => [0.22, 0.22, 0.24], Shade => [0.72, 0.73, 0.75], Metal => [0.35, 0.35, 0.37], Light => [1.0, 0.45, 0.12]]),
    arch!("shower_post", po::shower_post, [Metal], [Metal => [0.78, 0.79, 0.81], Top => [0.62, 0.46, 0.30], Handle => [0.70, 0.71, 0.73]]),
    arch!("sewing_machine", sw::sewing_machine, [Body], [Body => [0.93, 0.93, 0.91], Metal => [0.70, 0.71, 0.73], Handle => [0.55, 0.56, 0.58], Books => [0.80, 0.15, 0.25]]),
    arch!("sewing_table", sw::sewing_table, [Top, Body, Door, Frame], [Handle => [0.55, 0.56, 0.58], Books => [0.80, 0.15, 0.25]]),
    arch!("chess_table", bd::chess_table, [Top, Frame], [Canvas => [0.90, 0.84, 0.70], Interior => [0.28, 0.17, 0.10]]),
    arch!("air_hockey_table", bd::air_hockey_table, [Body, Frame], [Body => [0.12, 0.20, 0.45], Frame => [0.12, 0.20, 0.45], Canvas => [0.96, 0.96, 0.96], Handle => [0.85, 0.15, 0.12], Interior => BLACK]),
    arch!("dryer", la::dryer, [Body], [Body => WHITE, Door => [0.22, 0.23, 0.25], Top => [0.80, 0.81, 0.82], Metal => STEEL, Frame => [0.55, 0.55, 0.56], Handle => [0.74, 0.74, 0.76], Screen => [0.05, 0.07, 0.09]]),
    arch!("vanity", va::vanity, [Top, Body, Door], [Top => [0.93, 0.91, 0.87], Body => [0.93, 0.91, 0.87], Door => [0.95, 0.93, 0.89], Frame => [0.78, 0.66, 0.42], Canvas => MIRROR_GLASS, Handle => BRASS]),
    arch!("salon_station", va::salon_station, [Body, Door], [Body => [0.12, 0.12, 0.13], Door => [0.16, 0.16, 0.17], Top => WHITE, Frame => [0.20, 0.20, 0.21], Canvas => MIRROR_GLASS, Light => [1.0, 0.90, 0.65], Interior => BLACK, Metal => STEEL, Handle => STEEL]),
    arch!("footstool", va::footstool, [Upholstery], [Upholstery => [0.55, 0.45, 0.38], Cushion => [0.30, 0.24, 0.19], Frame => DARK_WOOD]),
    arch!("poker_table", jt::poker_table, [Upholstery], [Upholstery => [0.08, 0.42, 0.20], Cushion => [0.10, 0.09, 0.09], Frame => [0.36, 0.20, 0.10], Interior => BLACK]),
    arch!("cutting_table", jt::cutting_table, [Top, Body], [Top => [0.90, 0.88, 0.84], Body => WHITE, Frame => [0.85, 0.85, 0.84], Canvas => [0.15, 0.45, 0.32], Handle => [0.80, 0.88, 0.82], Metal => STEEL]),
    arch!("grooming_table", jt::grooming_table, [Upholstery], [Upholstery => [0.14, 0.14, 0.15], Cushion => [0.22, 0.22, 0.24], Metal => STEEL, Canvas => [0.75, 0.12, 0.12], Tyre => BLACK, Handle => BLACK]),
    arch!("produce_stand", jt::produce_stand, [Body, Frame], [Body => [0.50, 0.34, 0.20], Frame => [0.72, 0.56, 0.36], Canvas => [0.12, 0.16, 0.14], Handle => [0.92, 0.92, 0.88]]),
    arch!("cubicle", of::cubicle, [Upholstery], [Upholstery => [0.45, 0.50, 0.56], Metal => [0.70, 0.71, 0.73], Top => [0.80, 0.78, 0.74], Body => [0.28, 0.28, 0.30], Door => [0.34, 0.34, 0.36], Interior => BLACK, Canvas => [0.96, 0.92, 0.55], Handle => STEEL]),
    arch!("corkboard", of::corkboard, [Canvas], [Canvas => [0.72, 0.55, 0.36], Frame => [0.50, 0.34, 0.20], Handle => [0.80, 0.12, 0.10]]),
    arch!("ladder_shelf", of::ladder_shelf, [Frame, Top], [Frame => [0.55, 0.40, 0.25], Top => [0.55, 0.40, 0.25]]),
    arch!("kitchen_cart", su::kitchen_cart, [Frame, Body, Door], [Top => [0.72, 0.52, 0.32], Frame => [0.92, 0.92, 0.90], Body => [0.92, 0.92, 0.90], Door => [0.94, 0.94, 0.92], Handle => STEEL, Tyre => BLACK, Canvas => [0.70, 0.55, 0.33], Interior => [0.35, 0.25, 0.15], Metal => STEEL, Cushion => [0.80, 0.30, 0.25]]),
    arch!("candelabra", su::candelabra, [Metal], [Metal => [0.12, 0.12, 0.13], Body => [0.95, 0.92, 0.82], Light => [1.0, 0.80, 0.40]]),
    arch!("jukebox", am::jukebox, [Body], [Body => [0.45, 0.25, 0.12], Frame => [0.20, 0.12, 0.07], Upholstery => [0.95, 0.20, 0.15], Light => [1.0, 0.72, 0.20], Seat => [0.25, 0.55, 1.0], Interior => [0.06, 0.05, 0.05], BlackKeys => BLACK, Cushion => [0.90, 0.75, 0.20], Metal => [0.82, 0.82, 0.84], Keys => [0.95, 0.93, 0.88]]),
    arch!("pinball", am::pinball, [Body], [Body => [0.12, 0.12, 0.14], Top => BLACK, Canvas => [0.20, 0.45, 0.85], Upholstery => [0.90, 0.15, 0.15], Light => [1.0, 0.60, 0.15], Pane => [0.80, 0.86, 0.90], Metal => [0.82, 0.82, 0.84], Handle => [0.95, 0.85, 0.20], Interior => BLACK]),
    arch!("slot_machine", am::slot_machine, [Body], [Body => [0.65, 0.08, 0.10], Frame => BLACK, Light => [1.0, 0.78, 0.25], Metal => [0.82, 0.82, 0.84], Canvas => WHITE, Upholstery => [0.85, 0.10, 0.12], Top => BLACK, Keys => [0.95, 0.70, 0.15], Handle => [0.85, 0.10, 0.10], Interior => BLACK]),
    arch!("popcorn_machine", am::popcorn_machine, [Body, Door], [Body => [0.78, 0.10, 0.10], Door => [0.72, 0.09, 0.09], Frame => [0.20, 0.20, 0.21], Tyre => BLACK, Metal => STEEL, Top => STEEL, Pane => [0.85, 0.90, 0.90], Cushion => [0.98, 0.88, 0.50], Light => [1.0, 0.85, 0.30], Interior => BLACK]),
    arch!("scarecrow", ef::scarecrow, [Duvet], [Duvet => [0.62, 0.20, 0.16], Trunk => [0.45, 0.32, 0.20], Cushion => [0.86, 0.74, 0.42], Canvas => [0.78, 0.66, 0.48], Top => [0.55, 0.40, 0.22], Interior => BLACK]),
    arch!("statue", ef::statue, [Body, Top], [Body => [0.90, 0.89, 0.86], Top => [0.86, 0.85, 0.82]]),
    arch!("seated_statue", ef::seated_statue, [Body, Top], [Body => [0.90, 0.89, 0.86], Top => [0.80, 0.79, 0.76]]),
    arch!("pergola", by::pergola, [Frame, Top], [Frame => [0.62, 0.47, 0.32], Top => [0.58, 0.43, 0.28], Trunk => [0.35, 0.25, 0.15], Foliage => [0.25, 0.50, 0.20]]),
    arch!("mailbox", by::mailbox, [Body, Door], [Body => [0.20, 0.22, 0.24], Door => [0.20, 0.22, 0.24], Frame => [0.55, 0.42, 0.28], Handle => [0.85, 0.12, 0.10], Metal => STEEL]),
    arch!("hot_tub", by::hot_tub, [Body], [Body => [0.40, 0.30, 0.22], Frame => [0.34, 0.25, 0.18], Top => [0.55, 0.55, 0.57], Water => [0.30, 0.70, 0.82], Interior => [0.15, 0.35, 0.45], Cushion => [0.25, 0.25, 0.27], Canvas => WHITE]),
    arch!("fire_engine", en::fire_engine, [Body], [Body => [0.78, 0.08, 0.08], Canvas => WHITE, Top => [0.80, 0.81, 0.83], Frame => [0.55, 0.56, 0.58], Glass => [0.22, 0.27, 0.32], Interior => [0.10, 0.10, 0.11], Metal => [0.75, 0.76, 0.78], Light => [1.0, 0.95, 0.80], Seat => [0.20, 0.35, 1.0]]),
    arch!("repair_stand", rw::repair_stand, [Frame], [Frame => [0.13, 0.32, 0.66], Metal => STEEL, Handle => [0.80, 0.12, 0.10], Top => [0.16, 0.16, 0.17], Tyre => BLACK, Body => [0.16, 0.16, 0.17]]),
    arch!("school_desk", rw::school_desk, [Top], [Top => [0.80, 0.66, 0.46], Metal => [0.26, 0.27, 0.29], Body => [0.32, 0.33, 0.35]]),
    arch!("boxing_ring", rw::boxing_ring, [Frame], [Body => [0.10, 0.14, 0.35], Canvas => [0.90, 0.90, 0.87], Metal => STEEL, Handle => [0.80, 0.10, 0.10], Cushion => [0.12, 0.25, 0.70], Frame => [0.82, 0.10, 0.10], Top => [0.20, 0.20, 0.22]]),
    arch!("chest_freezer", rw::chest_freezer, [Body, Top], [Body => WHITE, Top => WHITE, Interior => [0.20, 0.20, 0.22], Handle => [0.30, 0.30, 0.32], Metal => STEEL, Light => [0.30, 0.90, 0.40]]),
    arch!("dartboard", rw::dartboard, [Frame], [Frame => [0.24, 0.15, 0.09], Interior => [0.06, 0.06, 0.07], Body => [0.07, 0.07, 0.08], Canvas => [0.92, 0.86, 0.68], Handle => [0.78, 0.12, 0.10], Top => [0.10, 0.50, 0.24]]),
    arch!("stepping_stones", rw::stepping_stones, [Stone], [Stone => [0.58, 0.56, 0.52]]),
    arch!("cooler", rw::cooler, [Body], [Body => [0.16, 0.36, 0.70], Top => WHITE, Interior => [0.10, 0.10, 0.12], Canvas => WHITE, Handle => [0.20, 0.20, 0.22]]),
    arch!("standing_desk", rw::standing_desk, [Top], [Top => [0.80, 0.66, 0.46], Metal => [0.15, 0.15, 0.16], Handle => [0.12, 0.12, 0.13]]),
    arch!("striped_towel", tx::striped_towel, [Body], [Body => [0.12, 0.42, 0.78], Canvas => WHITE, Cushion => [0.95, 0.72, 0.15]]),
    arch!("checked_blanket", tx::checked_blanket, [Body], [Body => [0.78, 0.12, 0.12], Canvas => WHITE, Cushion => [0.90, 0.60, 0.58]]),
    arch!("tiled_mat", tx::tiled_mat, [], []),
    arch!("paper_lantern", tx::paper_lantern, [Shade], [Shade => [0.98, 0.95, 0.86], Frame => [0.12, 0.12, 0.13], Metal => [0.85, 0.82, 0.74]]),
    arch!("potted_palm", pt::potted_palm, [Foliage], [Foliage => [0.26, 0.52, 0.20], Trunk => [0.42, 0.48, 0.26], Pot => [0.86, 0.85, 0.82]]),
    arch!("standing_statue", ef::standing_statue, [Body, Top], [Body => [0.90, 0.89, 0.86], Top => [0.86, 0.85, 0.82]]),
    arch!("pottery_wheel", nm::pottery_wheel, [Body], [Body => [0.90, 0.90, 0.88], Top => [0.62, 0.64, 0.66], Frame => [0.20, 0.20, 0.21], Metal => STEEL, Soil => [0.66, 0.44, 0.32], Handle => [0.15, 0.15, 0.16], Tyre => BLACK]),
    arch!("sarcophagus", nm::sarcophagus, [Body, Top], [Body => [0.70, 0.52, 0.22], Top => [0.80, 0.62, 0.26], Frame => [0.55, 0.50, 0.44], Skin => [0.92, 0.74, 0.30], Canvas => [0.12, 0.26, 0.55], Handle => [0.88, 0.70, 0.25]]),
    arch!("tripod_lamp", nm::tripod_lamp, [Shade], [Frame => [0.50, 0.34, 0.20], Metal => [0.20, 0.20, 0.21], Shade => [0.93, 0.90, 0.82], Light => [1.0, 0.92, 0.70]]),
    arch!("mushroom", nm::mushroom, [Shade], [Shade => [0.82, 0.12, 0.10], Trunk => [0.93, 0.90, 0.82], Interior => [0.90, 0.85, 0.74], Canvas => [0.97, 0.96, 0.93]]),
    arch!("pond", pond::pond, [Water], [Water => [0.16, 0.34, 0.38], Stone => [0.55, 0.54, 0.50], Foliage => [0.30, 0.50, 0.20], Body => [0.95, 0.45, 0.10], Canvas => [0.96, 0.95, 0.92]]),
    arch!("lake", nm::lake, [Water], [Water => [0.20, 0.42, 0.55], Soil => [0.40, 0.33, 0.22], Foliage => [0.45, 0.55, 0.25]]),
    arch!("sea", nm::sea, [Water], [Water => [0.12, 0.40, 0.60], Soil => [0.80, 0.70, 0.50], Interior => [0.58, 0.48, 0.33], Canvas => [0.95, 0.97, 0.98]]),
    arch!("printing_press", cn::printing_press, [Metal], [Metal => [0.16, 0.16, 0.17], Body => [0.22, 0.22, 0.23], Frame => [0.42, 0.28, 0.16], Handle => [0.72, 0.56, 0.28], Interior => [0.06, 0.06, 0.07], Canvas => [0.95, 0.93, 0.86]]),
    arch!("xray_machine", cn::xray_machine, [Body], [Body => [0.90, 0.91, 0.92], Metal => [0.62, 0.64, 0.67], Top => [0.80, 0.82, 0.84], Cushion => [0.22, 0.42, 0.62], Light => [1.0, 0.92, 0.55], Handle => [0.20, 0.20, 0.22]]),
    arch!("time_machine", cn::time_machine, [Metal], [Metal => BRASS, Handle => [0.80, 0.64, 0.32], Glass => [0.42, 0.30, 0.16], Light => [0.55, 0.85, 1.0], Top => [0.36, 0.22, 0.12], Frame => [0.30, 0.18, 0.10], Upholstery => [0.62, 0.08, 0.10], Body => [0.25, 0.16, 0.09], Canvas => [0.95, 0.92, 0.82]]),
    arch!("folding_chair", hf::folding_chair, [Seat], [Metal => [0.20, 0.20, 0.22], Handle => STEEL, Seat => [0.20, 0.20, 0.22]]),
    arch!("loft_bed", hf::loft_bed, [Frame], [Duvet => [0.35, 0.48, 0.66], Top => [0.80, 0.66, 0.46], Body => [0.85, 0.84, 0.80], Door => [0.88, 0.87, 0.83]]),
    arch!("watering_can", hf::watering_can, [Body], [Body => [0.25, 0.50, 0.30], Metal => [0.66, 0.67, 0.69], Handle => [0.25, 0.50, 0.30], Interior => BLACK]),
    arch!("wall_mirror", hf::wall_mirror, [Frame], [Frame => [0.72, 0.56, 0.28], Canvas => MIRROR_GLASS, Body => [0.35, 0.25, 0.16], Metal => STEEL]),
    arch!("window_seat", hf::window_seat, [Cushion], [Cushion => [0.36, 0.48, 0.62], Body => WHITE, Door => [0.95, 0.95, 0.94], Frame => WHITE, Top => [0.90, 0.90, 0.89], Interior => [0.55, 0.55, 0.55], Handle => BRASS, Pillow => [0.92, 0.86, 0.74]]),
    arch!("cutting_board", ky::cutting_board, [Top], [Top => [0.72, 0.52, 0.30], Interior => [0.45, 0.30, 0.16], Metal => [0.82, 0.83, 0.85], Handle => BLACK]),
    arch!("pot_rack", ky::pot_rack, [Pot], [Frame => [0.12, 0.12, 0.13], Metal => [0.30, 0.30, 0.32], Pot => [0.72, 0.40, 0.22], Handle => [0.20, 0.20, 0.21]]),
    arch!("sawhorse", ky::sawhorse, [Frame, Top], [Frame => [0.78, 0.64, 0.44], Top => [0.80, 0.66, 0.46]]),
    arch!("baby_gate", ky::baby_gate, [Frame], [Frame => [0.95, 0.95, 0.94], Handle => [0.55, 0.56, 0.58]]),
    arch!("step_stool", ky::step_stool, [Body], [Body => WHITE, Top => WHITE, Tyre => [0.30, 0.30, 0.32]]),
    arch!("air_purifier", ev::air_purifier, [Body], [Body => [0.93, 0.93, 0.92], Interior => [0.30, 0.31, 0.33], Light => [0.40, 0.75, 1.0]]),
    arch!("knife_block", ev::knife_block, [Body], [Body => [0.62, 0.44, 0.26], Handle => [0.10, 0.10, 0.11]]),
    arch!("towel_roll", ev::towel_roll, [Metal], [Metal => STEEL, Canvas => [0.97, 0.97, 0.95], Interior => [0.62, 0.50, 0.36], Handle => STEEL]),
    arch!("tricycle", ev::tricycle, [Body], [Body => [0.85, 0.12, 0.10], Tyre => BLACK, Metal => STEEL, Handle => [0.12, 0.12, 0.13], Seat => BLACK]),
    arch!("clothesline", ev::clothesline, [Frame], [Frame => [0.62, 0.64, 0.66], Metal => [0.85, 0.85, 0.85], Handle => [0.55, 0.40, 0.24]]),
    arch!("hose_reel", ev::hose_reel, [Pot], [Pot => [0.20, 0.55, 0.25], Frame => [0.22, 0.22, 0.24], Body => [0.22, 0.22, 0.24], Metal => STEEL, Handle => [0.95, 0.65, 0.10]]),
    arch!("surgical_light", sg::surgical_light, [Shade], [Shade => [0.92, 0.93, 0.94], Metal => [0.82, 0.83, 0.85], Frame => [0.85, 0.86, 0.87], Light => [1.0, 0.98, 0.92], Handle => [0.35, 0.55, 0.75]]),
    arch!("sectional", lo::sectional, [Upholstery, Cushion], [Frame => DARK_WOOD]),
    arch!("pulpit", pd::pulpit, [Body, Top, Door], [Body => [0.42, 0.27, 0.15], Top => [0.34, 0.21, 0.11], Door => [0.48, 0.31, 0.18], Frame => [0.34, 0.21, 0.11], Canvas => [0.42, 0.12, 0.40], Handle => BRASS]),
    arch!("hanging_scroll", hg::hanging_scroll, [Body], [Body => [0.56, 0.62, 0.50], Canvas => [0.94, 0.91, 0.82], Frame => [0.30, 0.20, 0.12], Handle => [0.20, 0.14, 0.09], Interior => [0.20, 0.20, 0.22], BlackKeys => [0.25, 0.22, 0.18], Cushion => [0.78, 0.14, 0.10]]),
    arch!("string_lights", hg::string_lights, [Light], [Light => [1.0, 0.86, 0.52], BlackKeys => [0.10, 0.10, 0.10], Metal => STEEL]),
    arch!("squat_rack", tr::squat_rack, [Frame], [Frame => [0.14, 0.14, 0.15], Metal => [0.12, 0.12, 0.13], Handle => STEEL, Interior => BLACK]),
    arch!("play_kitchen", pl::play_kitchen, [Body, Door], [Body => [0.96, 0.95, 0.92], Door => [0.98, 0.55, 0.62], Canvas => [0.50, 0.80, 0.86], Top => [0.86, 0.72, 0.52], Frame => [0.98, 0.55, 0.62], Handle => [0.98, 0.80, 0.18], BlackKeys => BLACK, Metal => STEEL, Screen => [0.10, 0.12, 0.14]]),
    arch!("dragon", lr::dragon, [Body], [Body => [0.50, 0.10, 0.08], Upholstery => [0.85, 0.62, 0.30], Canvas => [0.38, 0.07, 0.07], Frame => [0.32, 0.06, 0.05], Keys => [0.92, 0.88, 0.76], Light => [1.0, 0.85, 0.20], Top => [0.25, 0.05, 0.04]]),
    arch!("treasure_hoard", lr::treasure_hoard, [Metal], [Metal => [0.78, 0.56, 0.12], Handle => [1.0, 0.86, 0.36], Body => [0.92, 0.74, 0.28], Interior => [0.25, 0.16, 0.05], Cushion => [0.80, 0.06, 0.12], Glass => [0.12, 0.30, 0.85]]),
    arch!("bowl", bw::bowl, [Body], [Body => WHITE, Top => [0.35, 0.50, 0.70]]),
    arch!("toys", pl::toys, [Body], [Body => [0.86, 0.20, 0.14], Top => [0.95, 0.80, 0.20], Cushion => [0.20, 0.45, 0.85], Tyre => BLACK]),
    arch!("sack_of_presents", pk::sack_of_presents, [Canvas], [Canvas => [0.62, 0.48, 0.30], Frame => [0.80, 0.10, 0.10], Handle => [0.95, 0.80, 0.30], Cushion => [0.85, 0.12, 0.12], Top => [0.15, 0.55, 0.25], Pillow => [0.90, 0.90, 0.94], Shade => [0.20, 0.40, 0.85]]),
    arch!("periscope", sco::periscope, [Metal], [Metal => [0.40, 0.43, 0.41], Frame => [0.22, 0.24, 0.23], Body => [0.30, 0.33, 0.31], Screen => [0.05, 0.06, 0.08], Handle => [0.12, 0.12, 0.13]]),
];

/// Names of [`ARCHETYPES`], in order.
pub const NAMES: [&str; ARCHETYPES.len()] = {
    let mut out = [""; ARCHETYPES.len()];
    let mut i = 0;
    while i < ARCHETYPES.len() {
        out[i] = ARCHETYPES[i].name;
        i += 1;
    }
    out
};

/// The archetype named `name`; the default (`box`, first in the table) for other names.
pub fn get(name: &str) -> &'static Archetype {
    ARCHETYPES
        .iter()
        .find(|a| a.name == name)
        .unwrap_or(&ARCHETYPES[0])
}
