//! `DesignWriter` writes the same design files as `write_design`, byte for byte.

use garmentcode::io::{DesignWriter, write_design};
use garmentcode::{Params, Sampler, Value, sample_rng};
use garments::Design;

#[test]
fn random_designs_are_written_as_write_design_does() {
    let space = Design::design_space();
    let writer = DesignWriter::new(&space);
    assert!(writer.templated());
    let sampler = Sampler::new(space.clone());
    for i in 0..3000 {
        let d: Design = sampler.sample(&mut sample_rng(99, i));
        assert_eq!(writer.write(&d), write_design(&d, &space), "design {i}");
    }
    let d = Design::defaults();
    assert_eq!(writer.write(&d), write_design(&d, &space));
}

#[test]
fn awkward_numbers_are_written_as_write_design_does() {
    let space = Design::design_space();
    let writer = DesignWriter::new(&space);
    let floats = [0.0, -0.0, 1e-5, -3e-5, 1.5e-7, 0.0001, 1e16, 1.25e17, 123456789.125, 1.0 / 3.0, -0.5, 2.0];
    for (k, x) in floats.iter().enumerate() {
        let mut d = Design::defaults();
        for p in space.params() {
            let keys: Vec<&str> = p.path.split('.').collect();
            let v = match p.default {
                Value::Float(_) => Value::Float(*x),
                Value::Int(_) => Value::Int(-7 * k as i64),
                _ => continue,
            };
            d.set_value(&keys, &v).unwrap();
        }
        assert_eq!(writer.write(&d), write_design(&d, &space), "value {x}");
    }
}

#[test]
fn a_design_space_file_with_other_ranges_is_written_as_write_design_does() {
    let base = Design::design_space();
    let text = "design:\n  meta:\n    upper:\n      v: Shirt\n      range: [Shirt, null]\n      type: select_null\n      default_prob: 0.9\n  waistband:\n    waist:\n      v: 1.5\n      range: [1.2, 1.8]\n";
    let space = garmentcode::DesignSpace::from_yaml(text, "space.yaml", &base).unwrap();
    let writer = DesignWriter::new(&space);
    assert!(writer.templated());
    let sampler = Sampler::new(space.clone());
    for i in 0..200 {
        let d: Design = sampler.sample(&mut sample_rng(5, i));
        assert_eq!(writer.write(&d), write_design(&d, &space), "design {i}");
    }
}
