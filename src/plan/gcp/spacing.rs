//! The room people need round the functional groups, one place for every group layout (rows,
//! floors of tables, a seat's standing spot, a table's sides): a walkway, a seat's gap to its
//! table, the spot where a person stands to sit down.

/// A walkway (m): a person passing behind a seated row, between the seats of two tables or
/// beside a block of rows (0.9 m, the usual circulation behind seated rows; a 0.25 m radius
/// walker standing 0.15 m behind a chair drawn 0.1 m off its desk, on a navigation mesh of
/// 5 cm cells, needs about 0.75 m).
pub(super) const PASSAGE: f64 = 0.9;
/// The gap a seat keeps from its table or desk (m).
pub(super) const SEAT_GAP: f64 = 0.05;
/// Depth of the standing spot beside a seat (m): a person (0.6 m across) and a little room to
/// turn.
pub(super) const SPOT: f64 = 0.75;
/// Depth beyond a table's side for a seat and the person who sits down (m).
pub(super) const TABLE_ROOM: f64 = 1.2;
/// Things whose bottom is higher than this leave the floor below them free to stand on (m).
pub(super) const HEAD_HEIGHT: f64 = 1.9;
/// The clear gap between two rows of seats nobody draws up to anything (theatre seats, pews): a
/// walker (0.3 m radius, see `check::walk`) passes along the row, with a 10 cm cell to spare.
pub(super) const ROW_WALK: f64 = 2.0 * crate::plan::check::walk::AGENT_RADIUS + 0.1;
