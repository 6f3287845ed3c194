// write_hdf5_tables through deal.II's HDF5 wrapper.
#include "commands/hdf5_tables.h"

#include "base/atomic_file.h"
#include "base/number.h"

#include <deal.II/base/hdf5.h>

namespace gearfem::commands
{
  std::string dataset_name(const std::string &header)
  {
    std::string out;
    for (const char c : header)
      out += c == '/' ? std::string(" per ") : std::string(1, c);
    return out;
  }

  void write_hdf5_tables(const std::vector<std::pair<std::string, Table>> &tables,
                         const std::filesystem::path &file,
                         const std::map<std::string, std::string> &attributes)
  {
    // Every value is checked before the file is opened: an exception thrown while a
    // dealii::HDF5 object is open makes its destructor call MPI_Abort (the process dies
    // instead of reporting the bad value with exit status 2).
    for (const auto &[name, table] : tables)
      for (std::size_t i = 0; i < table.n_rows(); ++i)
        for (std::size_t c = 0; c < table.n_columns(); ++c)
          require_finite_output(table.row(i)[c], file.string(), "dataset '" + name + "/" + table.headers()[c] + "'");
    TemporaryPath tmp(file);
    {
      dealii::HDF5::File f(tmp.path().string(), dealii::HDF5::File::FileAccessMode::create);
      for (const auto &[k, v] : attributes)
        f.set_attribute(k, v);
      for (const auto &[name, table] : tables)
        {
          if (table.n_rows() == 0)
            continue;
          auto g = f.create_group(name);
          for (std::size_t c = 0; c < table.n_columns(); ++c)
            {
              std::vector<double> col(table.n_rows());
              for (std::size_t i = 0; i < table.n_rows(); ++i)
                col[i] = table.row(i)[c];
              g.write_dataset(dataset_name(table.headers()[c]), col);
            }
        }
    }
    tmp.commit();
  }
} // namespace gearfem::commands
