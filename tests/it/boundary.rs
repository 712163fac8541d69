//! The distance along a route to the nearest change of kind that
//! `examples/boundary_errors.rs` reports (docs/experiments.md, section 4),
//! on a route of known geometry.

#[path = "../../examples/common/boundary.rs"]
mod along;

fn kinds(k: &[&str]) -> Vec<String> {
    k.iter().map(|s| s.to_string()).collect()
}

/// Steps of 5 m (3-4-5, with a rise of 1 m that is not counted), 6 m,
/// 8 m and 2 m, turning twice: the distance is along the route, not
/// straight (scan 4 is 16.3 m from scan 0 in a straight line, 21 m driven).
const ROUTE: [[f64; 3]; 5] = [
    [0.0, 0.0, 0.0],
    [3.0, 4.0, 1.0],
    [3.0, 10.0, 0.0],
    [11.0, 10.0, 0.0],
    [11.0, 12.0, 0.0],
];

#[test]
fn distance_driven_sums_the_horizontal_steps_between_poses() {
    assert_eq!(
        along::distance_driven(&ROUTE),
        vec![0.0, 5.0, 11.0, 19.0, 21.0]
    );
    assert_eq!(along::distance_driven(&[]), Vec::<f64>::new());
}

#[test]
fn a_change_of_kind_lies_halfway_between_the_two_scans_on_either_side() {
    let driven = along::distance_driven(&ROUTE);
    // Changes between scans 1 and 2 (at 8 m driven) and 3 and 4 (at 20 m).
    let d = along::distance_to_change(&kinds(&["plain", "plain", "road", "road", "path"]), &driven);
    assert_eq!(
        d,
        vec![Some(8.0), Some(3.0), Some(3.0), Some(1.0), Some(1.0)]
    );
    // A return to an earlier kind is a change too.
    let d = along::distance_to_change(&kinds(&["plain", "road", "road", "road", "plain"]), &driven);
    assert_eq!(
        d,
        vec![Some(2.5), Some(2.5), Some(8.5), Some(1.0), Some(1.0)]
    );
}

#[test]
fn a_route_of_one_kind_has_no_change_to_be_near() {
    let driven = along::distance_driven(&ROUTE);
    let d = along::distance_to_change(&kinds(&["road"; 5]), &driven);
    assert_eq!(d, vec![None; 5]);
}
